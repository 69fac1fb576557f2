// Floor response spectra of a run (see floor_spectra.h).
#include "post/floor_spectra.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "solver/core/constants.h"

namespace isopound::post {
namespace {

std::optional<double> setting(const RunData& run, const char* key) {
  const nlohmann::json& s = run.summary;
  if (!s.is_object() || !s.contains("settings") || !s.at("settings").is_object()) return {};
  const nlohmann::json& j = s.at("settings");
  if (!j.contains(key) || !j.at(key).is_number()) return {};
  return j.at(key).get<double>();
}

std::string seconds(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g s", t);
  return b;
}

std::string number(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", x);
  return b;
}

// The largest interval <= limit that a user would type: 1, 2 or 5 times a power of ten.
double round_down_125(double limit) {
  const double decade = std::pow(10.0, std::floor(std::log10(limit)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * decade <= limit * (1 + 1e-12)) return m * decade;
  return decade;
}

// Keeps the periods the sampling resolves, or says why not (FloorSpectraError).
// `given`: the periods were asked for (not the defaults).
std::vector<double> resolved_periods(const std::vector<double>& asked, bool given,
                                     const HistorySampling& h, const FloorSpectraOptions& o,
                                     std::vector<std::string>& notes) {
  const double dt = h.effective(), t_min = o.samples_per_period * dt;
  std::vector<double> kept, dropped;
  for (double t : asked) (t == 0.0 || t >= t_min * (1 - 1e-9) ? kept : dropped).push_back(t);
  if (dropped.empty()) return kept;
  const double shortest = *std::min_element(dropped.begin(), dropped.end());
  // Which interval limits: the rows, or the solver's steps (rows inside a step are interpolated).
  const bool steps = h.analysis_interval > h.row_interval;
  const std::string sampled = steps ? "the solver's analysis interval is " + seconds(dt) +
                                          " (rows every " + seconds(h.row_interval) +
                                          " between its steps are interpolated)"
                                    : "histories.csv has a row every " + seconds(dt);
  const std::string needed = seconds(round_down_125(shortest / o.samples_per_period));
  const std::string rerun = "output.interval: " + needed + " or less" +
                            (steps ? " (and analysis.dt: " + needed + ")" : std::string());
  const bool refuse = o.short_periods == FloorSpectraOptions::ShortPeriods::kRefuse ||
                      (o.short_periods == FloorSpectraOptions::ShortPeriods::kAuto && given);
  if (refuse) {
    throw FloorSpectraError(
        sampled + ", too coarse for the period " + seconds(shortest) + ": the rule dt <= T/" +
        number(o.samples_per_period) + " allows T >= " + seconds(t_min) + ". Rerun with " +
        (steps ? "analysis.dt: " + needed + " and " : std::string()) +
        "output.interval: " + needed +
        " or less (output.interval 0 = every record sample, when the record's dt is that "
        "small), or ask for periods >= " +
        seconds(t_min) + " (--periods), or drop the short ones with --short-periods clip");
  }
  const double longest = *std::max_element(dropped.begin(), dropped.end());
  notes.push_back(
      std::to_string(dropped.size()) + " of the " + (given ? "periods asked" : "default periods") +
      ", " + seconds(shortest) + (dropped.size() > 1 ? " to " + seconds(longest) : std::string()) +
      ", dropped: " + sampled + " and the rule dt <= T/" + number(o.samples_per_period) +
      " needs T >= " + seconds(t_min) + "; a run with " + rerun + " computes them" +
      (given ? std::string() : " (--short-periods refuse: an error instead)"));
  if (std::none_of(kept.begin(), kept.end(), [](double t) { return t > 0.0; }))
    throw FloorSpectraError("no period left after clipping: every period asked is shorter than " +
                            seconds(t_min) + "; rerun with a smaller output.interval");
  return kept;
}

// x, y and RotD spectra of one plan point's acceleration pair (one SDOF history each).
template <class Motion>
void place_spectra(PlaceSpectra& p, const Motion& x, const Motion& y,
                   const std::vector<double>& periods, const SpectrumOptions& o) {
  PairSpectra s = pair_spectra(x, y, periods, o);
  p.x = std::move(s.first);
  p.y = std::move(s.second);
  p.rotd = std::move(s.rotd);
}

std::string level_of(const std::string& label) {
  const auto slash = label.find('/');
  return slash == std::string::npos ? label : label.substr(slash + 1);
}

// `motion(column, name)`: the history column `column` (an index into histories.csv's columns) as
// a GroundMotion (the rows) or an Accelerogram (the steps).
template <class MotionOf>
void spectra_2d(const RunData& run, const MotionOf& motion, const std::vector<double>& periods,
                const SpectrumOptions& o, FloorSpectra& out) {
  for (const Structure& s : run.structures)
    for (const Level& l : s.levels) {
      if (l.a_abs < 0)
        throw FloorSpectraError((run.dir / "histories.csv").string() + ": no '" + l.label +
                                " a_abs [m/s2]' column (absolute acceleration of the level)");
      PlaceSpectra p;
      p.label = l.label;
      p.structure = s.name;
      p.level = level_of(l.label);
      p.elevation = l.elevation;
      p.x = response_spectrum(motion(l.a_abs, l.label), periods, o);
      out.places.push_back(std::move(p));
    }
}

template <class MotionOf>
void spectra_3d(const RunData& run, const MotionOf& motion, const std::vector<double>& periods,
                const SpectrumOptions& o, FloorSpectra& out) {
  for (const Structure& s : run.structures)
    for (const Level& l : s.levels) {
      if (l.a_abs < 0 || l.a_abs_y < 0 || l.a_abs_theta < 0)
        throw FloorSpectraError((run.dir / "histories.csv").string() + ": '" + l.label +
                                "' lacks its (x), (y) or (theta) a_abs column");
      const PlanBody& body = run.site.bodies.at(l.body);
      if (body.role == "wall") continue;  // a flexible moat wall: not a floor
      const auto ax = motion(l.a_abs, l.label + " (x)");
      const auto ay = motion(l.a_abs_y, l.label + " (y)");
      const auto at = motion(l.a_abs_theta, l.label + " (theta)");
      std::vector<std::pair<std::string, Vec2>> points{{"CM", body.p_WCM}};
      for (std::size_t k = 0; k < body.plan_W.size(); ++k)
        points.push_back({"corner " + std::to_string(k + 1), body.plan_W[k]});
      for (const auto& [name, p_W] : points) {
        // The rigid diaphragm's point p: a_x − p_y a_θ, a_y + p_x a_θ (DOFs at the plan origin).
        auto px = ax, py = ay;
        px.name = l.label + "/" + name + " x";
        py.name = l.label + "/" + name + " y";
        for (std::size_t k = 0; k < at.acceleration.size(); ++k) {
          px.acceleration[k] -= p_W.y * at.acceleration[k];
          py.acceleration[k] += p_W.x * at.acceleration[k];
        }
        PlaceSpectra place;
        place.label = l.label + "/" + name;
        place.structure = s.name;
        place.level = level_of(l.label);
        place.elevation = l.elevation;
        place.p_W = p_W;
        place_spectra(place, px, py, periods, o);
        out.places.push_back(std::move(place));
      }
    }
}

// Ground and every place, from `motion` (see spectra_2d).
template <class MotionOf>
void all_spectra(const RunData& run, const MotionOf& motion, const SpectrumOptions& o,
                 FloorSpectra& out) {
  const int gx = run.find("", "ground_acceleration");
  if (gx < 0)
    throw FloorSpectraError((run.dir / "histories.csv").string() +
                            ": no 'ground_acceleration [m/s2]' column");
  out.ground.label = "ground";
  const auto ground_x = motion(gx, "ground x");
  if (run.three_d) {
    const int gy = run.find("", "ground_acceleration_y");
    auto ground_y = ground_x;
    ground_y.name = "ground y";
    if (gy >= 0) {
      ground_y.acceleration = motion(gy, "ground y").acceleration;
    } else {
      std::fill(ground_y.acceleration.begin(), ground_y.acceleration.end(), 0.0);
      out.notes.push_back("no ground_acceleration_y column: the ground moves along x only");
    }
    out.ground.p_W = Vec2{0.0, 0.0};
    place_spectra(out.ground, ground_x, ground_y, out.periods, o);
    spectra_3d(run, motion, out.periods, o, out);
  } else {
    out.ground.x = response_spectrum(ground_x, out.periods, o);
    spectra_2d(run, motion, out.periods, o, out);
  }
}

}  // namespace

HistorySampling history_sampling(const RunData& run) {
  const std::vector<double>& t = run.time();
  const std::size_t n = t.size();
  HistorySampling s;
  s.row_interval = setting(run, "output_interval_s").value_or((t.back() - t.front()) / (n - 1));
  s.analysis_interval = setting(run, "analysis_interval_s").value_or(0.0);
  const double dt = s.row_interval;
  // Rows at exactly k dt (docs/theory.md, "Output sampling"), times written to 9 digits.
  const double tolerance = 0.01 * dt + 1e-8 * std::max(std::abs(t.front()), std::abs(t.back()));
  if (!(dt > 0.0)) throw FloorSpectraError((run.dir / "histories.csv").string() + ": no time step");
  for (std::size_t k = 0; k < n; ++k)
    if (std::abs(t[k] - t.front() - static_cast<double>(k) * dt) > tolerance)
      throw FloorSpectraError((run.dir / "histories.csv").string() + ": row " +
                              std::to_string(k + 2) + " at t = " + seconds(t[k]) +
                              " is not on the uniform grid of " + seconds(dt) +
                              " (summary.json output_interval_s); spectra need uniform rows");
  return s;
}

GroundMotion column_motion(const RunData& run, int column, double dt, const std::string& name) {
  GroundMotion m;
  m.name = name;
  m.dt = dt;
  m.acceleration = run.column(column);
  return m;
}

FloorSpectra floor_spectra(const RunData& run, const FloorSpectraOptions& options) {
  for (double t : options.periods)
    if (!(t >= 0.0) || !std::isfinite(t))
      throw std::invalid_argument("periods must be finite and >= 0 s");
  if (!(options.samples_per_period >= 1.0))
    throw std::invalid_argument("samples per period must be >= 1");
  FloorSpectra out;
  out.three_d = run.three_d;
  out.damping = options.spectrum.damping;
  out.sampling = history_sampling(run);
  const bool given = !options.periods.empty();
  const SpectrumOptions& o = options.spectrum;
  using Source = FloorSpectraOptions::Source;
  std::optional<StepTable> steps;
  if (options.source != Source::kRows) {
    try {
      steps = read_step_accelerations(run);
    } catch (const RunDataError& e) {
      throw FloorSpectraError(e.what());
    }
    if (!steps && options.source == Source::kSteps)
      throw FloorSpectraError((run.dir / "step-accelerations.csv").string() +
                              ": absent (--from steps): rerun with output: {floor_spectra: true}");
  }
  if (steps) {
    // Every step, exact for the straight lines between them: every period is resolved.
    out.periods = given ? options.periods : default_periods();
    out.steps = steps->time().size();
    const auto motion = [&](int column, const std::string& name) {
      const int c = steps->find(run.columns.at(column));
      if (c < 0)
        throw FloorSpectraError((run.dir / "step-accelerations.csv").string() + ": no '" +
                                run.columns.at(column) + "' column");
      return Accelerogram{name, steps->time(), steps->values[c]};
    };
    all_spectra(run, motion, o, out);
    return out;
  }
  out.periods = resolved_periods(given ? options.periods : default_periods(), given, out.sampling,
                                 options, out.notes);
  const double dt = out.sampling.row_interval;
  if (options.source == Source::kAuto) {  // one line with the clipping note, if any
    const std::string caveat =
        "spectra from the rows of histories.csv (every " + seconds(out.sampling.effective()) +
        "), where an impact shorter than a few rows is smoothed away; a run with output: "
        "{floor_spectra: true} records every analysis step and gives them exactly";
    if (out.notes.empty())
      out.notes.push_back(caveat);
    else
      out.notes.back() += "; " + caveat;
  }
  const auto motion = [&](int column, const std::string& name) {
    return column_motion(run, column, dt, name);
  };
  all_spectra(run, motion, o, out);
  return out;
}

std::string floor_spectra_csv(const FloorSpectra& f) {
  std::vector<const PlaceSpectra*> all{&f.ground};
  for (const PlaceSpectra& p : f.places) all.push_back(&p);
  std::ostringstream csv;
  csv.precision(10);
  csv << "period_s,damping_ratio";
  for (const PlaceSpectra* p : all) {
    if (!f.three_d) {
      csv << "," << p->label << " PSA [g]," << p->label << " SD [m]";
      continue;
    }
    for (const char* q : {"PSA", "SD"})
      for (const char* c : {"x", "y", "RotD50", "RotD100"})
        csv << "," << p->label << " " << q << "_" << c << (q[0] == 'P' ? " [g]" : " [m]");
  }
  csv << "\n";
  for (std::size_t i = 0; i < f.periods.size(); ++i) {
    csv << f.periods[i] << "," << f.damping;
    for (const PlaceSpectra* p : all) {
      if (!f.three_d) {
        csv << "," << p->x.psa[i] / kGravity << "," << p->x.sd[i];
        continue;
      }
      csv << "," << p->x.psa[i] / kGravity << "," << p->y->psa[i] / kGravity << ","
          << p->rotd->psa50[i] / kGravity << "," << p->rotd->psa100[i] / kGravity;
      csv << "," << p->x.sd[i] << "," << p->y->sd[i] << "," << p->rotd->sd50[i] << ","
          << p->rotd->sd100[i];
    }
    csv << "\n";
  }
  return csv.str();
}

std::string floor_spectra_places_csv(const FloorSpectra& f) {
  std::ostringstream csv;
  csv.precision(10);
  csv << "label,structure,level,x_m,y_m,elevation_m\n";
  const auto row = [&](const PlaceSpectra& p) {
    csv << p.label << "," << p.structure << "," << p.level << ",";
    if (p.p_W)
      csv << p.p_W->x << "," << p.p_W->y;
    else
      csv << ",";
    csv << "," << p.elevation << "\n";
  };
  row(f.ground);
  for (const PlaceSpectra& p : f.places) row(p);
  return csv.str();
}

}  // namespace isopound::post
