// The capacity-curve figure of a pushover: base shear [kN] against roof displacement [cm] with the
// first-yield and capping points marked and named, beside the storey drift ratios [%] against the
// roof displacement (which storey concentrates the drift), the same points marked on them. An
// isolated building (PushoverData::isolated) is drawn against its superstructure's drift instead,
// with a panel between of the base shear against the bearings' displacement (the same points).
#pragma once

#include <vector>

#include "post/figure.h"
#include "post/pushover_data.h"
#include "post/xy_plot.h"

namespace isopound::post {

// Marker fills of the two points (no series colour is close to either).
constexpr Rgb kFirstYieldColour{255, 190, 0};    // amber circle
constexpr Rgb kCappingColour{200, 0, 160};       // magenta diamond
constexpr Rgb kBearingCurveColour{140, 86, 75};  // the bearings' curve (series_colour(5))

// Panel 0: the capacity curve; isolated, panel 1: the bearings' curve; last (when the table has
// storey columns): storey drift ratios. `frames` receives where each panel's data lands
// (PanelFrame::to_pixel takes cm and kN / %).
Figure pushover_figure(const PushoverData& data, std::vector<PanelFrame>* frames = nullptr);

}  // namespace isopound::post
