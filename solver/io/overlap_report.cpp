// JSON for `isopound geometry overlap`: the Overlap's fields under keys that carry their units.
// Points and directions are null when the polygons are separated (nothing defines them).
#include "solver/io/overlap_report.h"

namespace isopound {
namespace {

using Json = nlohmann::ordered_json;

Json point(Vec2 p) {
  return Json::array({p.x, p.y});
}

}  // namespace

Json overlap_json(int index, const std::string& name, const Overlap& overlap,
                  const Separation& separation) {
  Json out;
  out["pair"] = index;
  if (!name.empty()) out["name"] = name;
  out["case"] = std::string(to_string(overlap.kind));
  out["area_m2"] = overlap.area;
  const bool apart = overlap.kind == OverlapCase::kSeparated;
  out["centroid_m"] = apart ? Json() : point(overlap.p_WC);
  out["crossings_m"] = apart ? Json() : Json::array({point(overlap.p_WP1), point(overlap.p_WP2)});
  out["normal"] = apart ? Json() : point(overlap.n_AB);
  out["tangent"] = apart ? Json() : point(overlap.t_AB);
  out["indentation_m"] = overlap.indentation;
  out["mean_depth_m"] = overlap.mean_depth;
  out["vertices"] = overlap.vertex_count;
  Json polygon = Json::array();
  for (int k = 0; k < overlap.vertex_count; ++k) polygon.push_back(point(overlap.vertices[k]));
  out["polygon_m"] = polygon;
  out["separation_m"] = separation.distance;
  return out;
}

Json plan_overlap_json(int index, const std::string& name, const PlanOverlap& overlap,
                       const Separation& separation) {
  Json out;
  out["pair"] = index;
  if (!name.empty()) out["name"] = name;
  out["case"] = "contacts";
  out["contacts"] = overlap.count;
  double area = 0.0;
  Json components = Json::array();
  for (int k = 0; k < overlap.count; ++k) {
    area += overlap.components[k].area;
    Json c = overlap_json(k, "", overlap.components[k], separation);
    c.erase("pair");
    c.erase("separation_m");
    components.push_back(c);
  }
  out["area_m2"] = area;
  out["components"] = components;
  out["separation_m"] = separation.distance;
  return out;
}

std::string overlaps_text(const std::vector<Json>& objects) {
  std::string text = "[";
  for (std::size_t k = 0; k < objects.size(); ++k) {
    text += k == 0 ? "\n  {" : ",\n  {";
    bool first = true;
    for (const auto& [key, value] : objects[k].items()) {
      text += (first ? "\n    " : ",\n    ") + Json(key).dump() + ": ";
      first = false;
      if (!value.is_array() || value.empty() || !value.front().is_object()) {
        text += value.dump();
        continue;
      }
      // A list of objects (a non-convex pair's components): one object per line.
      for (std::size_t c = 0; c < value.size(); ++c)
        text += (c == 0 ? "[\n      " : ",\n      ") + value[c].dump();
      text += "\n    ]";
    }
    text += "\n  }";
  }
  return text + "\n]\n";
}

}  // namespace isopound
