// 3D run figures (see plot_run3d.h).
#include "post/plot_run3d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "geometry/overlap.h"
#include "post/xy_plot.h"
#include "solver/core/constants.h"

namespace isopound::post {
namespace {

// Displacement (or absolute acceleration) history of a plan point p of a level.
struct PlanHistory {
  std::vector<double> x, y, resultant;
};
PlanHistory point_history(const RunData& run, const Level& l, Vec2 p, bool acceleration) {
  PlanHistory h;
  const int cx = acceleration ? l.a_abs : l.u, cy = acceleration ? l.a_abs_y : l.u_y,
            ct = acceleration ? l.a_abs_theta : l.theta;
  for (std::size_t r = 0; r < run.rows(); ++r) {
    const double u = cx >= 0 ? run.values[cx][r] : 0.0, v = cy >= 0 ? run.values[cy][r] : 0.0,
                 th = ct >= 0 ? run.values[ct][r] : 0.0;
    h.x.push_back(u - p.y * th);
    h.y.push_back(v + p.x * th);
    h.resultant.push_back(std::hypot(h.x.back(), h.y.back()));
  }
  return h;
}

std::string short_label(const std::string& label, const RunData& run) {
  if (run.structures.size() == 1) {
    const auto slash = label.find('/');
    if (slash != std::string::npos) return label.substr(slash + 1);
  }
  return label;
}

// The structure's base slab (wherever it sits: isolated above a storey, it is not the lowest
// level), else its lowest level.
const Level* base_level(const RunData& run, const Structure& s) {
  for (const Level& l : s.levels)
    if (run.site.bodies[l.body].level == "base") return &l;
  return nullptr;
}

const Structure& main_structure(const RunData& run) {
  // The first isolated structure (with a base slab), else the first.
  for (const Structure& s : run.structures)
    if (base_level(run, s)) return s;
  return run.structures.front();
}

}  // namespace

std::vector<CornerDrift> corner_drifts(const RunData& run) {
  std::vector<CornerDrift> out;
  for (const Structure& s : run.structures) {
    for (std::size_t k = 0; k < s.levels.size(); ++k) {
      const Level& hi = s.levels[k];
      const Level* lo = k > 0 ? &s.levels[k - 1] : nullptr;  // nullptr: the ground
      const PlanBody& body = run.site.bodies[hi.body];
      // Storey f ends at floor f; the base slab ends the isolation layer, no storey.
      if (body.level.rfind("floor ", 0) != 0) continue;
      const int storey = std::atoi(body.level.c_str() + 6);
      const double h = body.elevation - (lo ? run.site.bodies[lo->body].elevation : 0.0);
      CornerDrift best;
      for (std::size_t c = 0; c < body.plan_W.size(); ++c) {
        const PlanHistory up = point_history(run, hi, body.plan_W[c], false);
        PlanHistory down;
        if (lo) down = point_history(run, *lo, body.plan_W[c], false);
        CornerDrift d;
        d.label = s.name + "/story " + std::to_string(storey) + " corner " + std::to_string(c + 1);
        for (std::size_t r = 0; r < run.rows(); ++r) {
          const double dx = up.x[r] - (lo ? down.x[r] : 0.0), dy = up.y[r] - (lo ? down.y[r] : 0.0);
          d.ratio.push_back(std::hypot(dx, dy) / h);
          d.peak = std::max(d.peak, d.ratio.back());
        }
        if (d.peak >= best.peak || best.ratio.empty()) best = std::move(d);
      }
      out.push_back(std::move(best));
    }
  }
  return out;
}

std::vector<NamedFigure> run_figures3d(const RunData& run) {
  const std::vector<double>& t = run.time();
  const Structure& main = main_structure(run);
  const Level& base = base_level(run, main) ? *base_level(run, main) : main.levels.front();
  const PlanBody& base_body = run.site.bodies[base.body];
  std::vector<NamedFigure> out;

  // ---- time histories
  std::vector<Panel> panels;
  const PlanHistory cm = point_history(run, base, base_body.p_WCM, false);
  Panel disp{short_label(base.label, run) + ": displacement of the centre of mass",
             "time [s]",
             "displacement [cm]",
             {},
             true,
             true};
  disp.series.push_back(line_series("x", t, scaled(cm.x, 0.01)));
  disp.series.push_back(line_series("y", t, scaled(cm.y, 0.01)));
  disp.series.push_back({"resultant", t, scaled(cm.resultant, 0.01), Rgb{0, 0, 0}, 1.5});
  mark_reported_peaks(disp,
                      {reported_level_peak(run, base.label, "displacement", "x"),
                       reported_level_peak(run, base.label, "displacement", "y"),
                       reported_level_peak(run, base.label, "displacement", "resultant")},
                      0.01, "cm");
  panels.push_back(disp);

  Panel drift{"Corner drift ratios (the worst corner of each storey)",
              "time [s]",
              "drift ratio [%]",
              {},
              true,
              false,
              true};
  std::vector<std::optional<ReportedPeak>> drift_peaks;
  for (const CornerDrift& d : corner_drifts(run)) {
    drift.series.push_back(line_series(short_label(d.label, run), t, scaled(d.ratio, 0.01)));
    // "<building>/story <k> corner <c>": summary.json's largest corner-column peak of storey k.
    const auto slash = d.label.find('/');
    drift_peaks.push_back(reported_drift_ratio_peak(run, d.label.substr(0, slash),
                                                    std::atoi(d.label.c_str() + slash + 7)));
  }
  mark_reported_peaks(drift, drift_peaks, 0.01, "%");
  panels.push_back(drift);

  // Absolute accelerations (resultants at the centres of mass); summary.json has the ground's
  // a_x and a_y peaks, not the resultant's.
  std::vector<PeakedSeries> accelerations;
  const int gx = run.find("", "ground_acceleration"), gy = run.find("", "ground_acceleration_y");
  if (gx >= 0) {
    std::vector<double> g(t.size());
    for (std::size_t r = 0; r < t.size(); ++r)
      g[r] = std::hypot(run.values[gx][r], gy >= 0 ? run.values[gy][r] : 0.0) / kGravity;
    accelerations.push_back({{"ground (resultant)", t, g, Rgb{120, 120, 120}, 1.2}, std::nullopt});
  }
  const Level* slab = base_level(run, main);
  int slab_index = -1;
  for (const Structure& s : run.structures)
    for (const Level& l : s.levels)
      if (l.a_abs >= 0) {
        if (&l == slab) slab_index = static_cast<int>(accelerations.size());
        accelerations.push_back(
            {line_series(
                 short_label(l.label, run), t,
                 scaled(point_history(run, l, run.site.bodies[l.body].p_WCM, true).resultant,
                        kGravity)),
             reported_level_peak(run, l.label, "absolute_acceleration")});
      }
  for (Panel& p :
       acceleration_panels(std::move(accelerations), slab_index,
                           {short_label(base.label, run) +
                                ": absolute acceleration at the centre of mass (resultant)",
                            "Absolute accelerations of the floors and the ground (resultant at the "
                            "centres of mass)",
                            "Absolute accelerations at the centres of mass (resultant)"},
                           false))
    panels.push_back(std::move(p));

  if (!run.contact_log.pairs.empty()) {
    double peak = 0.0;
    for (const auto& [pair, rows] : run.contact_log.pairs)
      for (const ContactEvent& e : rows)
        peak = std::max({peak, std::abs(e.normal_force), std::abs(e.tangential_force)});
    std::string unit;
    const double div = force_scale(peak, unit);
    Panel normal{"Normal contact forces F_N (event log: every step in contact)",
                 "time [s]",
                 "F_N [" + unit + "]",
                 {},
                 true,
                 false,
                 true};
    Panel tangential{"Tangential contact forces F_T (event log; on B: F_N n − F_T t)",
                     "time [s]",
                     "F_T [" + unit + "]",
                     {},
                     true,
                     true};
    std::vector<std::optional<ReportedPeak>> fn_peaks, ft_peaks;
    for (const auto& [pair, rows] : run.contact_log.pairs) {
      fn_peaks.push_back(reported_element_peak(run, pair, "normal_force"));
      ft_peaks.push_back(reported_element_peak(run, pair, "tangential_force"));
      // Zero from the start and between episodes (the log holds in-contact and separation rows).
      std::vector<double> tt{t.front()}, fn{0.0}, ft{0.0};
      for (const ContactEvent& e : rows) {
        if (e.event == "onset") tt.push_back(e.time), fn.push_back(0.0), ft.push_back(0.0);
        tt.push_back(e.time);
        fn.push_back(e.normal_force / div);
        ft.push_back(e.tangential_force / div);
      }
      tt.push_back(t.back()), fn.push_back(0.0), ft.push_back(0.0);
      const std::string name = short_label(pair, run);
      normal.series.push_back(line_series(name, tt, fn));
      tangential.series.push_back(line_series(name, tt, ft));
    }
    mark_reported_peaks(normal, fn_peaks, div, unit);
    mark_reported_peaks(tangential, ft_peaks, div, unit);
    panels.push_back(normal);
    panels.push_back(tangential);
  }
  NamedFigure th{"time_histories.png", {}, {}};
  for (Panel& p : panels) p.legend_above_data = true;
  th.figure = xy_figure(panels, 1, 1000, kHistoryPanelHeight * static_cast<int>(panels.size()) + 40,
                        "Time histories: " + run.dir.filename().string() + " (" +
                            sampled_every(run) + "; ◆ peaks over every step, summary.json)",
                        &th.frames);
  out.push_back(std::move(th));

  // ---- bearings: force vs deformation per direction, and the orbit
  std::vector<Panel> loops;
  std::vector<const ElementColumns*> bearings;
  for (const ElementColumns& e : run.isolators)
    if (e.force_x >= 0 && e.deformation_x >= 0 && e.force_y >= 0 && e.deformation_y >= 0)
      bearings.push_back(&e);
  if (!bearings.empty()) {
    double peak = 0.0;
    for (const ElementColumns* e : bearings)
      peak = std::max({peak, peak_of(run.column(e->force_x)), peak_of(run.column(e->force_y))});
    std::string unit;
    const double div = force_scale(peak, unit);
    // A few bearings each in its colour and named; more of them (all alike but for the
    // torsion) thin grey under one legend entry, the one deformed farthest in colour and named.
    const bool each = bearings.size() <= 6;
    std::size_t far = 0;
    double far_peak = 0.0;  // m, the largest resultant deformation
    for (std::size_t k = 0; k < bearings.size(); ++k) {
      const std::vector<double>& ux = run.column(bearings[k]->deformation_x);
      const std::vector<double>& uy = run.column(bearings[k]->deformation_y);
      for (std::size_t r = 0; r < ux.size(); ++r)
        if (std::hypot(ux[r], uy[r]) > far_peak) far_peak = std::hypot(ux[r], uy[r]), far = k;
    }
    Panel px{"Bearings, x", "deformation u_x [cm]", "force F_x [" + unit + "]", {}, true, true};
    Panel py{"Bearings, y", "deformation u_y [cm]", "force F_y [" + unit + "]", {}, true, true};
    Panel orbit{"Bearing orbit", "deformation u_x [cm]", "deformation u_y [cm]", {}, true};
    orbit.equal_axes = true;
    for (Panel* p : {&px, &py, &orbit}) p->legend_at = Panel::LegendAt::kBest;
    const auto add = [&](const ElementColumns& e, std::string label, std::optional<Rgb> colour,
                         double width) {
      const std::vector<double> ux = scaled(run.column(e.deformation_x), 0.01),
                                uy = scaled(run.column(e.deformation_y), 0.01);
      px.series.push_back({label, ux, scaled(run.column(e.force_x), div), colour, width});
      py.series.push_back({label, uy, scaled(run.column(e.force_y), div), colour, width});
      orbit.series.push_back({std::move(label), ux, uy, colour, width});
    };
    char far_text[64];
    std::snprintf(far_text, sizeof far_text, " (largest: %.3g cm)", 100 * far_peak);
    for (std::size_t k = 0; k < bearings.size(); ++k) {
      const std::string label = short_label(bearings[k]->label, run);
      if (each)
        add(*bearings[k], k == far ? label + far_text : label, std::nullopt, 1.5);
      else if (k != far)
        add(*bearings[k],
            k == (far == 0 ? 1 : 0) ? "all " + std::to_string(bearings.size()) + " bearings" : "",
            Rgb{185, 185, 185}, 0.8);
    }
    if (!each)
      add(*bearings[far], short_label(bearings[far]->label, run) + far_text, Rgb{214, 39, 40}, 1.6);
    loops = {px, py, orbit};
    NamedFigure hysteresis{"hysteresis.png", {}, {}};
    hysteresis.figure =
        xy_figure(loops, 3, 1500, 480,
                  "Bearings: " + run.dir.filename().string() + " (" + sampled_every(run) + ")",
                  &hysteresis.frames);
    out.push_back(std::move(hysteresis));
  }

  // ---- contacts: F_N against the indentation δ_N and F_T against F_N per pair (event log)
  if (!run.contact_log.pairs.empty()) {
    std::vector<Panel> contact_panels;
    for (const auto& [pair, rows] : run.contact_log.pairs) {
      double peak = 0.0;
      for (const ContactEvent& e : rows)
        peak = std::max({peak, std::abs(e.normal_force), std::abs(e.tangential_force)});
      std::string unit;
      const double div = force_scale(peak, unit);
      Panel pn{short_label(pair, run),
               "indentation δ_N [mm]",
               "F_N [" + unit + "]",
               {},
               false,
               false,
               true};
      Panel pt{short_label(pair, run), "F_N [" + unit + "]", "F_T [" + unit + "]", {}, true, true};
      pt.legend_at = Panel::LegendAt::kBest;
      // One line per episode (onset to separation), so that episodes are not joined.
      Series n_line{"", {}, {}, Rgb{214, 39, 40}, 1.2},
          t_line{"F_T (a line per episode)", {}, {}, Rgb{255, 127, 14}, 1.2};
      const auto flush = [&] {
        if (n_line.x.empty()) return;
        pn.series.push_back(n_line), pt.series.push_back(t_line);
        t_line.label = "";  // the first episode names them all
        n_line.x.clear(), n_line.y.clear(), t_line.x.clear(), t_line.y.clear();
      };
      for (const ContactEvent& e : rows) {
        if (e.event == "onset") flush();
        if (!e.in_contact) continue;
        n_line.x.push_back(1e3 * e.indentation);
        n_line.y.push_back(e.normal_force / div);
        t_line.x.push_back(e.normal_force / div);
        t_line.y.push_back(e.tangential_force / div);
      }
      flush();
      // The friction limits |F_T| = μ F_N (stick below μ_s F_N, slip at μ_k F_N), drawn up to
      // 1.2 times the pair's peak |F_T|: the cone near the origin where the pair slides, without
      // letting μ F_N at the largest F_N (far above any F_T) set the axis.
      if (const auto f = run.friction.find(pair); f != run.friction.end()) {
        double fn_max = 0.0, ft_max = 0.0;
        for (const ContactEvent& e : rows)
          if (e.in_contact)
            fn_max = std::max(fn_max, e.normal_force / div),
            ft_max = std::max(ft_max, std::abs(e.tangential_force) / div);
        const auto limit = [&](double mu, const char* name, Rgb colour) {
          if (!(mu > 0.0) || !(fn_max > 0.0)) return;
          const double fn = std::min(fn_max, 1.2 * std::max(ft_max, 1e-9) / mu);
          char label[64];
          std::snprintf(label, sizeof label, "±%s F_N, %s = %g", name, name, mu);
          pt.series.push_back({label, {0.0, fn}, {0.0, mu * fn}, colour, 1.6});
          pt.series.push_back({"", {0.0, fn}, {0.0, -mu * fn}, colour, 1.6});
        };
        limit(f->second.mu_static, "μ_s", Rgb{40, 40, 40});
        limit(f->second.mu_kinetic, "μ_k", Rgb{31, 119, 180});
      }
      contact_panels.push_back(pn);
      contact_panels.push_back(pt);
    }
    const int rows_c = static_cast<int>(contact_panels.size() / 2);
    NamedFigure contacts{"contacts.png", {}, {}};
    contacts.figure = xy_figure(
        contact_panels, 2, 1100, 360 * rows_c + 40,
        "Contacts: " + run.dir.filename().string() + " (event log: every step in contact)",
        &contacts.frames);
    out.push_back(std::move(contacts));
  }

  // ---- base slab trajectory: its displacements (centre of mass and corners) with the walls'
  // clearance lines {d : d . n = gap} (n: from the slab at rest towards the wall), the axes set
  // by the motion; beside it an inset of the slab and walls at true scale (corners numbered).
  Panel plan{"In plan, true scale", "x [m]", "y [m]", {}, false};
  plan.equal_axes = true;
  const auto outline = [](const std::vector<Vec2>& poly, std::vector<double>& x,
                          std::vector<double>& y) {
    for (Vec2 p : poly) x.push_back(p.x), y.push_back(p.y);
    x.push_back(poly.front().x), y.push_back(poly.front().y);
  };
  Series rest{"slab at rest", {}, {}, Rgb{120, 120, 120}, 1.2};
  outline(base_body.plan_W, rest.x, rest.y);
  plan.series.push_back(rest);
  Panel orbit{short_label(base.label, run) + ": displacement of the centre of mass and corners",
              "u_x [cm]",
              "u_y [cm]",
              {},
              true};
  orbit.equal_axes = true;
  orbit.legend_at = Panel::LegendAt::kBest;
  bool wall_legend = true;
  double reach = 0.0, gap_min = 0.0;  // cm: the largest displacement, the smallest wall gap
  std::size_t reach_corner = 0;
  std::vector<PlanHistory> corners;
  for (Vec2 p : base_body.plan_W) corners.push_back(point_history(run, base, p, false));
  for (std::size_t c = 0; c < corners.size(); ++c)
    if (100 * peak_of(corners[c].resultant) > reach)
      reach = 100 * peak_of(corners[c].resultant), reach_corner = c;
  for (const PlanBody& w : run.site.bodies) {
    if (w.role != "wall") continue;
    Series ws{"", {}, {}, Rgb{150, 60, 40}, 2.0};
    outline(w.plan_W, ws.x, ws.y);
    plan.series.push_back(ws);
    const Separation sep = plan_separation(base_body.plan_W, w.plan_W);
    const double gap = 100 * sep.distance;  // cm
    gap_min = wall_legend ? gap : std::min(gap_min, gap);
    const Vec2 n = sep.n_AB, tangent{-n.y, n.x};
    const double half = std::max(reach, gap) * 1.2;
    orbit.series.push_back({wall_legend ? "wall clearance (a corner at the wall)" : "",
                            {gap * n.x - half * tangent.x, gap * n.x + half * tangent.x},
                            {gap * n.y - half * tangent.y, gap * n.y + half * tangent.y},
                            Rgb{150, 60, 40},
                            2.0});
    wall_legend = false;
  }
  Series cm_path{"centre of mass", {}, {}, Rgb{0, 0, 0}, 1.5};
  for (std::size_t r = 0; r < run.rows(); ++r) {
    cm_path.x.push_back(base_body.p_WCM.x + cm.x[r]);
    cm_path.y.push_back(base_body.p_WCM.y + cm.y[r]);
  }
  plan.series.push_back(cm_path);
  orbit.series.push_back(
      {"centre of mass", scaled(cm.x, 0.01), scaled(cm.y, 0.01), Rgb{0, 0, 0}, 1.5});
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const Rgb colour = series_colour(static_cast<int>(c));
    orbit.series.push_back({"corner " + std::to_string(c + 1), scaled(corners[c].x, 0.01),
                            scaled(corners[c].y, 0.01), colour, 1.0});
    plan.marks.push_back(
        {base_body.plan_W[c].x, base_body.plan_W[c].y, std::to_string(c + 1), colour});
  }
  NamedFigure traj{"trajectory.png", {}, {}};
  Figure& fig = traj.figure;
  fig.width = 1400, fig.height = 700;
  fig.texts.push_back(
      {{700, 692},
       "Base slab trajectory: " + run.dir.filename().string() + " (" + sampled_every(run) + ")",
       15,
       Rgb{},
       HAlign::kCentre,
       VAlign::kTop,
       0.0,
       true});
  traj.frames.push_back(add_panel(fig, orbit, 0, 0, 900, 666));
  traj.frames.push_back(add_panel(fig, plan, 900, 250, 500, 416));
  char last[128];
  std::snprintf(last, sizeof last, "Largest corner displacement %.3g cm (corner %zu)", reach,
                reach_corner + 1);
  const std::string gap_text = wall_legend ? "." : "; wall gap " + [&] {
    char g[32];
    std::snprintf(g, sizeof g, "%.3g cm.", gap_min);
    return std::string(g);
  }();
  const std::string note[] = {"Inset: the slab at rest (grey, corners numbered), the moat",
                              "walls (brown) and the path of the centre of mass (black),",
                              "at true scale.", last + gap_text};
  for (int k = 0; k < 4; ++k)
    fig.texts.push_back({{985, 225.0 - 18 * k}, note[k], 11, Rgb{}, HAlign::kLeft, VAlign::kTop});
  out.push_back(std::move(traj));
  return out;
}

}  // namespace isopound::post
