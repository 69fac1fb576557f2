// plan.png of isopound-pre as a post::Figure (plain data; post/render_png draws it): the site to
// scale in the plan frame W (x to the right = east, y up = north), slabs, columns with their
// orientation, bearings, walls, the measured gaps dimensioned, centres of mass and stiffness, the
// record's L direction, a legend and a scale bar; with floor-to-column pounding (issue 26), every
// column a slab can strike drawn in kStruckColour and labelled with the storeys struck there,
// the legend naming each striking slab (structure, level, elevation) and the storey it strikes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/pre/checks.h"
#include "geometry/pre/properties.h"
#include "post/figure.h"
#include "solver/structures/site_plan.h"
#include "solver/structures/struck_columns3d.h"

namespace isopound::pre {

// The drawing's map from plan (m) to pixels (origin bottom-left, y up): p_px = origin_px +
// scale (p_W - origin_W).
struct PlanView {
  double scale = 1.0;  // px per m
  Vec2 origin_W;
  post::Point2 origin_px;
  post::Point2 to_px(Vec2 p) const {
    return {origin_px.x + scale * (p.x - origin_W.x), origin_px.y + scale * (p.y - origin_W.y)};
  }
};

struct PlanOptions {
  std::string title;
  std::optional<double> angle;  // rad, L direction counter-clockwise from x
  int width = 1400, height = 1000;
  double max_dimensioned_gap = 2.0;  // m: larger clearances are not dimensioned
};

// Colours (the tests look for them).
inline constexpr post::Rgb kColumnColour{20, 20, 20};
inline constexpr post::Rgb kBearingColour{230, 120, 0};
inline constexpr post::Rgb kWallColour{110, 110, 110};
inline constexpr post::Rgb kMassColour{200, 0, 0};
inline constexpr post::Rgb kStiffnessColour{0, 90, 200};
inline constexpr post::Rgb kStruckColour{220, 0, 220};  // struck columns
post::Rgb slab_fill(int structure);                     // a light tint of the structure's colour

post::Figure plan_figure(const Site& site, const std::vector<StructureProperties>& properties,
                         const std::vector<Clearance>& clearances,
                         const std::vector<StruckColumnSite>& struck, const PlanOptions& options,
                         PlanView* view = nullptr);

}  // namespace isopound::pre
