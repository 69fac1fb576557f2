// The sweep plot as a Figure (xy_plot.h's style): one line per curve of SweepPlotData in
// series_colour order, each over its ensemble min–max band (a light tint of its colour) if any.
#pragma once

#include "post/figure.h"
#include "post/sweep_plot.h"
#include "post/xy_plot.h"

namespace isopound::post {

// The band's tint of a curve colour: a quarter of the colour, three quarters white.
Rgb band_tint(Rgb colour);

// `frame` (optional) receives where the data lands, for tests.
Figure sweep_plot_figure(const SweepPlotData& data, int width = 1000, int height = 640,
                         PanelFrame* frame = nullptr);

}  // namespace isopound::post
