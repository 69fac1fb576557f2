// Named peaks of two runs compared value by value (the convergence tests of the default stepping):
// the worst relative difference and where it is.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace isopound::test {

struct NamedPeak {
  std::string name;
  double value;
};

// |a/ref - 1|; 0 when both are 0 (e.g. a wall never hit), infinite when only ref is 0.
inline double relative_difference(double a, double ref) {
  if (a == ref) return 0.0;
  if (ref == 0.0) return std::numeric_limits<double>::infinity();
  return std::abs(a / ref - 1.0);
}

struct Comparison {
  double worst = 0.0;
  std::string where = "-";
};

// The two lists must name the same peaks in the same order (a test failure otherwise).
inline Comparison compare(const std::vector<NamedPeak>& run, const std::vector<NamedPeak>& ref) {
  Comparison c;
  EXPECT_EQ(run.size(), ref.size());
  for (std::size_t i = 0; i < std::min(run.size(), ref.size()); ++i) {
    EXPECT_EQ(run[i].name, ref[i].name);
    const double d = relative_difference(run[i].value, ref[i].value);
    if (d > c.worst || std::isnan(d)) {
      c.worst = d;
      c.where = run[i].name;
    }
  }
  return c;
}

// Every peak leaf ({"value", "unit"}) of a summary tree, by path: (value, unit).
inline void peak_leaves(const nlohmann::json& node, const std::string& path,
                        std::map<std::string, std::pair<double, std::string>>& out) {
  if (node.is_object() && node.contains("value") && node.contains("unit")) {
    out[path] = {node["value"].get<double>(), node["unit"].get<std::string>()};
    return;
  }
  if (node.is_object())
    for (const auto& [k, v] : node.items()) peak_leaves(v, path + "/" + k, out);
  if (node.is_array())
    for (std::size_t i = 0; i < node.size(); ++i)
      peak_leaves(node[i], path + "/" + std::to_string(i), out);
}

}  // namespace isopound::test
