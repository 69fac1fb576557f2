// Reading the 3D contact law (interface: contact3d_input.h).
#include "solver/io/contact3d_input.h"

#include "solver/io/model_input.h"
#include "solver/structures/pounding3d.h"

namespace isopound {

ModelConfig::Contact3D read_contact3d(const InputNode& node) {
  node.expect_keys({"k_normal",
                    "k_tangential",
                    "materials",
                    "mu_static",
                    "mu_kinetic",
                    "restitution",
                    "friction",
                    "keep_tension",
                    "indentation",
                    "overlap",
                    "impact_count",
                    "elevation_tolerance",
                    "search_distance",
                    "law",
                    "k",
                    "k_h",
                    "n",
                    "e",
                    "material",
                    "xi_formula",
                    "min_impact_velocity"});
  ModelConfig::Contact3D c;
  PolygonContactConfig& law = c.law;
  if (node.has("law")) {
    c.use_impact_law = true;
    read_impact_law(node, c.impact_law);
    if (node.has("k_normal") || node.has("restitution"))
      node.fail_at_key(node.has("k_normal") ? "k_normal" : "restitution",
                       "not used with law: (the 2D law's own k and e act along the normal)");
  }
  if (const auto m = node.find("materials")) {
    m->expect_keys({"E", "nu"});
    if (node.has("k_normal") || node.has("k_tangential"))
      m->fail("give either materials or k_normal/k_tangential, not both");
    const double e = m->required("E").quantity(dim::kPressure, Bound::kPositive);
    const InputNode nu_node = m->required("nu");
    const double nu = nu_node.number(Bound::kNonNegative);
    if (nu >= 0.5) nu_node.fail("Poisson's ratio must be in [0, 0.5)");
    const ContactStiffness k = contact_stiffness_from_materials(e, nu, e, nu);
    law.k_normal = k.k_normal;
    law.k_tangential = k.k_tangential;
  } else {
    if (!c.use_impact_law)
      node.read_quantity("k_normal", dim::kPressure, Bound::kPositive, law.k_normal);
    node.read_boolean("friction", law.friction);
    if (law.friction)
      node.read_quantity("k_tangential", dim::kStiffness, Bound::kPositive, law.k_tangential);
  }
  if (node.has("materials")) node.read_boolean("friction", law.friction);
  if (law.friction) {
    node.read_number("mu_static", Bound::kNonNegative, law.mu_static);
    node.read_number("mu_kinetic", Bound::kNonNegative, law.mu_kinetic);
    if (law.mu_kinetic > law.mu_static) node.fail_at_key("mu_kinetic", "must not exceed mu_static");
  } else {
    for (const char* key : {"mu_static", "mu_kinetic", "k_tangential"})
      if (const auto n = node.find(key)) n->fail("not used with friction: false");
  }
  if (!c.use_impact_law) {
    if (const auto e = node.find("restitution")) {
      law.restitution = e->number(Bound::kPositive);
      if (law.restitution > 1.0) e->fail("the coefficient of restitution must be in (0, 1]");
    } else {
      node.note_default("restitution", "0.65");
    }
    node.read_boolean("keep_tension", law.keep_tension);
    node.read_choice<IndentationRule>(
        "indentation",
        {{"thesis", IndentationRule::kThesis}, {"mean_depth", IndentationRule::kMeanDepth}},
        law.indentation);
  }
  node.read_choice<OverlapMethod>(
      "overlap", {{"fast", OverlapMethod::kFast}, {"exact", OverlapMethod::kExact}}, law.overlap);
  node.read_choice<ImpactCount>(
      "impact_count",
      {{"force_pulses", ImpactCount::kForcePulses}, {"onsets", ImpactCount::kOnsets}},
      law.impact_count);
  node.read_quantity("elevation_tolerance", dim::kLength, Bound::kPositive, c.elevation_tolerance);
  node.read_quantity("search_distance", dim::kLength, Bound::kPositive, c.search_distance);
  return c;
}

}  // namespace isopound
