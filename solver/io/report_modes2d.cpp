// The 2D modes table (see report_modes2d.h); the format of main.cpp's print_building_modes.
#include "solver/io/report_modes2d.h"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "solver/core/analysis.h"
#include "solver/core/modes.h"
#include "solver/structures/building2d.h"
#include "solver/structures/isolator.h"

namespace isopound {

void print_modes2d(std::ostream& out, const BuildingConfig& b) {
  char line[512];
  out << "Structure '" << b.name << "'\n";
  const auto show = [&](const std::string& title, const Modes& m,
                        const std::vector<std::string>& labels) {
    std::snprintf(line, sizeof line,
                  "%s\n  mode  period [s]  eff. mass [%%]  shape (%s ... %s, max = 1)\n",
                  title.c_str(), labels.front().c_str(), labels.back().c_str());
    out << line;
    for (int j = 0; j < m.period.size(); ++j) {
      std::snprintf(line, sizeof line, "  %4d  %10.4f  %13.1f  ", j + 1, m.period[j],
                    100 * m.effective_mass_ratio[j]);
      out << line;
      const double scale = m.shape.col(j).cwiseAbs().maxCoeff();
      for (int i = 0; i < m.shape.rows(); ++i) {
        std::snprintf(line, sizeof line, " %+.3f", m.shape(i, j) / scale);
        out << line;
      }
      out << '\n';
    }
  };
  const int k = b.isolated ? b.isolation_level : 0;
  std::vector<std::string> floor_labels;
  for (std::size_t i = static_cast<std::size_t>(k); i < b.floors.size(); ++i)
    floor_labels.push_back("floor " + std::to_string(i + 1));
  const ShearStick fixed = fixed_base_superstructure(b);
  show("Fixed-base superstructure",
       compute_modes(fixed.stiffness, fixed.mass, Eigen::VectorXd::Ones(fixed.mass.rows())),
       floor_labels);
  if (k > 0) {
    std::vector<std::string> sub_labels;
    for (int i = 0; i < k; ++i) sub_labels.push_back("floor " + std::to_string(i + 1));
    const ShearStick sub = fixed_base_substructure(b);
    show("Fixed-base substructure (alone)",
         compute_modes(sub.stiffness, sub.mass, Eigen::VectorXd::Ones(sub.mass.rows())),
         sub_labels);
  }
  if (!b.isolated) return;
  Model model = make_model(b);
  const StructureInfo& info = model.structures.front();
  std::vector<std::string> labels;  // levels in elevation order
  for (const int d : info.level_dofs)
    labels.push_back(model.dofs[d].label.substr(b.name.size() + 1));
  const int base = info.level_dofs[static_cast<std::size_t>(info.base_level)];
  const int bottom = info.isolator_bottom_dof();
  const IsolatorProperties p =
      isolator_properties(b.isolator, k > 0 ? isolated_mass(b) : model.total_mass());
  for (const auto& [name, stiffness] :
       {std::pair{"post-yield stiffness K_post", p.post_yield_stiffness},
        std::pair{"initial stiffness K_el", p.elastic_stiffness}}) {
    if (b.isolator.model == IsolatorConfig::Model::kLinear && stiffness != p.post_yield_stiffness)
      continue;
    // The storeys at rest (a yielding storey's initial tangent is in its element, not in
    // model.stiffness), and the isolation layer as a spring between the slab and what it
    // stands on.
    Eigen::MatrixXd K = stiffness_at_rest(model, info.isolator_element);
    K(base, base) += stiffness;
    if (bottom >= 0) {
      K(bottom, bottom) += stiffness;
      K(base, bottom) -= stiffness;
      K(bottom, base) -= stiffness;
    }
    show(std::string("Isolated, isolators at their ") + name + " = " +
             std::to_string(stiffness / 1e6) + " MN/m",
         compute_modes(K, model.mass, model.influence), labels);
  }
  std::snprintf(line, sizeof line,
                "Isolators: K_post %.4g N/m, F_y %.4g N, K_el %.4g N/m, alpha %.4f, Q %.4g N\n",
                p.post_yield_stiffness, p.yield_force, p.elastic_stiffness, p.alpha,
                p.characteristic_strength);
  out << line;
}

}  // namespace isopound
