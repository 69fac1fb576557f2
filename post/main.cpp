// isopound-post: plots of a run, response spectra of records, polar figures of a study, capacity
// curves of a pushover and ParaView animations. Headless by default (a private Xvfb when there is
// no DISPLAY). Exit codes: 0 success, 2 bad input (message names the file / key), 1 anything else.
#include <CLI/CLI.hpp>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "post/animate_command.h"
#include "post/command_support.h"
#include "post/floor_spectra.h"
#include "post/headless.h"
#include "post/plot_floor_spectra.h"
#include "post/plot_pushover.h"
#include "post/plot_run.h"
#include "post/plot_spectra.h"
#include "post/polar_study.h"
#include "post/pushover_data.h"
#include "post/render_png.h"
#include "post/run_data.h"
#include "post/spectra.h"
#include "post/sweep_plot.h"
#include "post/sweep_plot_figure.h"
#include "post/xy_plot.h"
#include "solver/core/constants.h"
#include "solver/excitation/ground_motion.h"
#include "solver/io/report.h"
#include "solver/study/cli_contract.h"

namespace fs = std::filesystem;
using namespace isopound;
using namespace isopound::post;

namespace {

// A damping ratio the SDOF recurrence takes: below critical (the plausibility row allows 1).
void check_damping(double ratio) {
  if (!(ratio < 1.0))
    throw BadInput("--damping: must be below 100 % (critical damping), got " +
                   readable_number(100.0 * ratio) + " %");
}

// ---- spectra -----------------------------------------------------------------------------

struct SpectraArgs {
  std::vector<std::string> records;
  bool pair = false;
  double damping = 0.05;  // ratio
  std::string out = "spectra";
  std::string unit;  // g | m/s2 | cm/s2 (columns)
  double dt = 0.0;
  int column = 0;
  int time_column = -1;
  double scale = 1.0;
  int oversample = 1;
};

GroundMotion load(const std::string& path, const SpectraArgs& a) {
  RecordReadOptions o;
  o.column = a.column;
  o.time_column = a.time_column;
  o.dt = a.dt;
  o.scale = a.scale;
  if (a.unit == "g" || a.unit.empty())
    o.unit = AccelerationUnit::kG;
  else if (a.unit == "m/s2")
    o.unit = AccelerationUnit::kMetrePerSecond2;
  else if (a.unit == "cm/s2")
    o.unit = AccelerationUnit::kCentimetrePerSecond2;
  else
    throw BadInput("--unit: '" + a.unit + "' is not one of g, m/s2, cm/s2");
  if (!fs::exists(path)) throw BadInput(path + ": record not found");
  try {
    return read_record(path, o);
  } catch (const RecordError& e) {
    throw BadInput(e.file() + (e.line() > 0 ? ":" + std::to_string(e.line()) : "") + ": " +
                   e.what());
  }
}

int run_spectra(const SpectraArgs& a) {
  if (a.pair && a.records.size() % 2 != 0)
    throw BadInput("--pair: give the records two by two (component 1, component 2, ...); got " +
                   std::to_string(a.records.size()));
  check_damping(a.damping);
  if (a.oversample < 1) throw BadInput("--oversample: must be >= 1");
  std::vector<GroundMotion> motions;
  for (const std::string& r : a.records) motions.push_back(load(r, a));
  SpectrumOptions opt;
  opt.damping = a.damping;
  opt.oversample = a.oversample;
  const std::vector<double> periods = default_periods();
  fs::create_directories(a.out);

  std::vector<Spectrum> spectra;
  Progress progress("spectra", motions.size());
  for (const GroundMotion& m : motions) {
    spectra.push_back(response_spectrum(m, periods, opt));
    progress.tick(spectra.size());
  }
  const SpectrumStatistics st = spectrum_statistics(spectra);
  std::vector<RotDSpectrum> rotd;
  if (a.pair)
    for (std::size_t i = 0; i + 1 < motions.size(); i += 2) {
      try {
        rotd.push_back(rotd_spectrum(motions[i], motions[i + 1], periods, opt));
      } catch (const std::invalid_argument& e) {
        throw BadInput(e.what());
      }
    }

  // CSV: the damping ratio, PSA in g and SD in m per record; for a set the log-space median
  // exp(mean ln), σ_ln and the band exp(mean ln ∓ σ_ln) (spectra.h); RotD.
  std::ostringstream csv;
  csv.precision(10);
  csv << "period_s,damping_ratio";
  for (const Spectrum& s : spectra) csv << "," << s.name << "_PSA_g," << s.name << "_SD_m";
  const bool stats = spectra.size() > 1;
  if (stats)
    csv << ",median_PSA_g,sigma_ln_PSA,median_minus_sigma_ln_PSA_g,median_plus_sigma_ln_PSA_g"
        << ",median_SD_m,sigma_ln_SD,median_minus_sigma_ln_SD_m,median_plus_sigma_ln_SD_m";
  for (const RotDSpectrum& r : rotd)
    csv << "," << r.name << "_RotD50_PSA_g," << r.name << "_RotD100_PSA_g," << r.name
        << "_RotD50_SD_m," << r.name << "_RotD100_SD_m";
  csv << "\n";
  for (std::size_t i = 0; i < periods.size(); ++i) {
    csv << periods[i] << "," << a.damping;
    for (const Spectrum& s : spectra) csv << "," << s.psa[i] / kGravity << "," << s.sd[i];
    if (stats)
      csv << "," << st.median_psa[i] / kGravity << "," << st.sigma_ln_psa[i] << ","
          << st.lower_psa[i] / kGravity << "," << st.upper_psa[i] / kGravity << ","
          << st.median_sd[i] << "," << st.sigma_ln_sd[i] << "," << st.lower_sd[i] << ","
          << st.upper_sd[i];
    for (const RotDSpectrum& r : rotd)
      csv << "," << r.psa50[i] / kGravity << "," << r.psa100[i] / kGravity << "," << r.sd50[i]
          << "," << r.sd100[i];
    csv << "\n";
  }
  write_text(fs::path(a.out) / "spectra.csv", csv.str());

  const PrivateDisplay display;
  render_png(spectra_figure(spectra, st, rotd, 100.0 * a.damping),
             (fs::path(a.out) / "spectra.png").string());
  std::printf("Wrote %s/spectra.csv and %s/spectra.png\n", a.out.c_str(), a.out.c_str());
  return kOk;
}

// ---- plot / animate -------------------------------------------------------------------------

int run_plot(const std::string& dir, const std::string& out, const std::string& model) {
  const RunData run = load_run(dir, model);
  const fs::path out_dir = out.empty() ? fs::path(dir) : fs::path(out);
  fs::create_directories(out_dir);
  const auto figures = run_figures(run);
  const PrivateDisplay display;
  for (const NamedFigure& f : figures) {
    render_png(f.figure, (out_dir / f.file).string());
    std::printf("Wrote %s\n", (out_dir / f.file).string().c_str());
  }
  return kOk;
}

// ---- polar ------------------------------------------------------------------------------------

int run_polar(const std::string& db, PolarStudyOptions opt, const std::vector<std::string>& where,
              const std::string& out) {
  opt.where = parse_where(where);
  PolarStudyResult r;
  try {
    r = read_polar_study(db, opt);
  } catch (const PolarStudyError& e) {
    throw BadInput(e.what());
  }
  for (const std::string& n : r.notes) std::fprintf(stderr, "isopound-post: note: %s\n", n.c_str());
  // -o as for every command: the output directory (default: the database's), or a .png file
  // (its .csv beside it).
  const std::string name = fs::path(db).stem().string() + "-polar-" + opt.quantity +
                           (opt.contour_axis.empty() ? "" : "-" + opt.contour_axis);
  const std::string stem = study_figure_stem(db, out, name);
  write_text(stem + ".csv", r.csv);
  const PrivateDisplay display;
  render_png(opt.contour_axis.empty() ? polar_envelope_figure(r.envelope)
                                      : polar_contour_figure(r.contour),
             stem + ".png");
  std::printf("Wrote %s.png and %s.csv\n", stem.c_str(), stem.c_str());
  return kOk;
}

// ---- sweep-plot -------------------------------------------------------------------------------

// A peak against a swept axis; -o as for polar: a directory (default: the database's) or a .png.
int run_sweep_plot(const std::string& db, SweepPlotOptions opt,
                   const std::vector<std::string>& where, const std::string& out) {
  opt.where = parse_where(where);
  SweepPlotData data;
  try {
    data = read_sweep_plot(db, opt);
  } catch (const SweepPlotError& e) {
    throw BadInput(e.what());
  }
  for (const std::string& n : data.notes)
    std::fprintf(stderr, "isopound-post: note: %s\n", n.c_str());
  const std::string name = fs::path(db).stem().string() + "-sweep-" + opt.output + "-" + opt.x_axis;
  const std::string stem = study_figure_stem(db, out, name);
  write_text(stem + ".csv", sweep_plot_csv(data));
  const PrivateDisplay display;
  render_png(sweep_plot_figure(data), stem + ".png");
  std::printf("Wrote %s.png and %s.csv\n", stem.c_str(), stem.c_str());
  return kOk;
}

// ---- pushover ---------------------------------------------------------------------------------

// `out`: a .png file, or a directory to write pushover.png into (default: the pushover directory).
int run_pushover(const std::string& dir, const std::string& out) {
  PushoverData data;
  try {
    data = read_pushover(dir);
  } catch (const PushoverDataError& e) {
    throw BadInput(e.what());
  }
  fs::path png = out.empty() ? fs::path(dir) / "pushover.png" : fs::path(out);
  if (!out.empty() && png.extension() != ".png" && png.extension() != ".PNG") png /= "pushover.png";
  if (!png.parent_path().empty()) fs::create_directories(png.parent_path());
  const PrivateDisplay display;
  render_png(pushover_figure(data), png.string());
  std::printf("Wrote %s\n", png.string().c_str());
  return kOk;
}

// ---- floor spectra ----------------------------------------------------------------------------

struct FloorSpectraArgs {
  std::string dir, out, model;
  double damping = 0.05;  // ratio
  std::vector<double> periods;
  double samples_per_period = 10.0;
  std::string short_periods;  // refuse | clip; "": clip the default periods, refuse those given
  int oversample = 1;
  std::string from;  // steps | rows; "": the steps when the run has them
};

// Spectra of every level's absolute acceleration (docs/floor-spectra.md); `out` a directory
// (default: the run directory).
int run_floor_spectra(const FloorSpectraArgs& a) {
  check_damping(a.damping);
  if (a.oversample < 1) throw BadInput("--oversample: must be >= 1");
  if (!a.short_periods.empty() && a.short_periods != "refuse" && a.short_periods != "clip")
    throw BadInput("--short-periods: '" + a.short_periods + "' is not refuse or clip");
  if (!a.from.empty() && a.from != "steps" && a.from != "rows")
    throw BadInput("--from: '" + a.from + "' is not steps or rows");
  const RunData run = load_run(a.dir, a.model);
  FloorSpectraOptions opt;
  opt.periods = a.periods;
  opt.spectrum.damping = a.damping;
  opt.spectrum.oversample = a.oversample;
  opt.samples_per_period = a.samples_per_period;
  using ShortPeriods = FloorSpectraOptions::ShortPeriods;
  opt.short_periods = a.short_periods == "clip"     ? ShortPeriods::kClip
                      : a.short_periods == "refuse" ? ShortPeriods::kRefuse
                                                    : ShortPeriods::kAuto;
  using Source = FloorSpectraOptions::Source;
  opt.source = a.from == "steps"  ? Source::kSteps
               : a.from == "rows" ? Source::kRows
                                  : Source::kAuto;
  FloorSpectra f;
  try {
    f = floor_spectra(run, opt);
  } catch (const FloorSpectraError& e) {
    throw BadInput(e.what());
  } catch (const std::invalid_argument& e) {
    throw BadInput(e.what());
  }
  for (const std::string& n : f.notes) std::fprintf(stderr, "isopound-post: note: %s\n", n.c_str());
  const fs::path out_dir = a.out.empty() ? fs::path(a.dir) : fs::path(a.out);
  fs::create_directories(out_dir);
  write_text(out_dir / "floor-spectra.csv", floor_spectra_csv(f));
  write_text(out_dir / "floor-spectra-places.csv", floor_spectra_places_csv(f));
  const PrivateDisplay display;
  render_png(floor_spectra_figure(f), (out_dir / "floor-spectra.png").string());
  char source[64];
  if (f.steps > 0)
    std::snprintf(source, sizeof source, "every analysis step: %zu", f.steps);
  else
    std::snprintf(source, sizeof source, "history every %.4g s", f.sampling.row_interval);
  std::printf(
      "Wrote %s/floor-spectra.csv, floor-spectra-places.csv and floor-spectra.png (%zu "
      "places, %zu periods, %s)\n",
      out_dir.string().c_str(), f.places.size(), f.periods.size(), source);
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
#ifdef __GLIBC__
  // VTK's zlib compressor allocates and frees ~256 kB per data array of every .vtu frame; with
  // glibc's default trim threshold each free hands the top of the heap back to the kernel and
  // the next frame faults it in again: animate spent 4/5 of its time there (9 s -> 2 s for a
  // 318-frame 3D run). Kept up to 64 MB instead.
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
  CLI::App app{
      "isopound-post: plots, response spectra, polar figures, capacity curves and animations"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("isopound-post ") + kIsopoundVersion);

  CliWarnings warnings;  // implausible quantity options, printed after parsing
  SpectraArgs sa;
  auto* spectra =
      app.add_subcommand("spectra", "5 %-damped PSA and SD spectra of records (CSV, PNG)");
  spectra->add_option("records", sa.records, "record files (PEER .AT2 or columns)")->required();
  spectra->add_flag("--pair", sa.pair, "records two by two form horizontal pairs: RotD50/RotD100");
  quantity_option(spectra->add_option("--damping", sa.damping,
                                      "damping ratio, e.g. '5 %' (default 5 %; a bare number is a "
                                      "ratio: 0.05)"),
                  {dim::kNone, "damping.ratio"}, &warnings);
  spectra->add_option("-o,--output,--out", sa.out, "output directory (default: spectra)");
  spectra->add_option("--unit", sa.unit, "columns files: g | m/s2 | cm/s2");
  quantity_option(spectra->add_option(
                      "--dt", sa.dt, "columns files without a time column: time step, e.g. '5 ms'"),
                  {dim::kTime, "ground_motion.dt", true}, &warnings);
  spectra->add_option("--column", sa.column, "columns files: acceleration column (0-based)");
  spectra->add_option("--time-column", sa.time_column, "columns files: time column (0-based)");
  quantity_option(spectra->add_option("--scale", sa.scale, "multiplies the acceleration"),
                  {dim::kNone, "ground_motion.scale"}, &warnings);
  spectra->add_option("--oversample", sa.oversample,
                      "sub-steps per record step for the peak (exact either way; default 1)");

  std::string run_dir, out, model;
  auto* plot = app.add_subcommand("plot", "time histories and hysteresis loops of a run (PNG)");
  plot->add_option("run_dir", run_dir, "directory with histories.csv and summary.json")->required();
  plot->add_option("-o,--output,--out", out, "output directory (default: the run directory)");
  plot->add_option("--model", model, "model file (default: the one named in summary.json)");

  AnimateArgs aa;
  auto* animate = app.add_subcommand(
      "animate", "ParaView animation of a run (.pvd + .vtu frames + view.py), slowed at impacts");
  animate->add_option("run_dir", run_dir, "directory with histories.csv and summary.json")
      ->required();
  animate->add_option("--scale", aa.frame.scale, "displacement magnification (default 1)");
  animate->add_option("--fps", aa.timeline.fps,
                      "regular frames per second of analysis time (default 25, thinned down to 5 "
                      "to fit --max-frames)");
  animate->add_flag("--uniform", aa.timeline.uniform,
                    "only the regular frames (no extra frames inside contact episodes)");
  animate->add_option("--impact-frames", aa.timeline.frames_per_episode,
                      "frames inside each contact episode, start and end included (default 12, "
                      "thinned down to 8 to fit --max-frames; at least 8)");
  animate->add_option("--max-frames", aa.timeline.max_frames,
                      "frame budget of the whole animation (default 1500): defaults are thinned "
                      "to fit it, with a note");
  animate->add_option("-o,--output,--out", out, "output directory (default: RUN_DIR/animation)");
  quantity_option(animate->add_option("--start", aa.timeline.start,
                                      "time of the first frame, e.g. '2 s' (default 0)"),
                  {dim::kTime});
  quantity_option(
      animate->add_option("--end", aa.timeline.end,
                          "time of the last frame, e.g. '8 s' (default: end of the run)"),
      {dim::kTime});
  quantity_option(animate->add_option("--preview", aa.preview,
                                      "also write preview.png of the frame at this time (s)"),
                  {dim::kTime});
  animate->add_option("--model", model, "model file (default: the one named in summary.json)");
  quantity_option(animate->add_option(
                      "--force-length", aa.frame.force_length,
                      "drawn length of the run's largest contact force, e.g. '3 m' (default 3 m)"),
                  {dim::kLength, "", true});
  animate->add_option("--exaggerate", aa.exaggeration,
                      "view.py draws contact overlaps this many times deeper (default: automatic, "
                      "the deepest about 5 % of the drawing)");
  animate->add_option("--view-scale", aa.view_scale,
                      "view.py draws displacements this many times larger, gaps too (default: "
                      "automatic, the largest 4 to 10 % of the site; SCALE at the top of view.py)");
  animate->add_option("--render", aa.render,
                      "also render through view.py with pvpython, headless: png | video | "
                      "FILE.avi | FILE.ogv");

  std::string db;
  PolarStudyOptions po;
  std::vector<std::string> where;
  auto* polar = app.add_subcommand("polar", "polar envelope / contour of a study (PNG, CSV)");
  polar->add_option("study_db", db, "the study's SQLite database")->required();
  polar->add_option("--quantity", po.quantity, "an output column of the study")->required();
  polar->add_option("--where", where, "AXIS=VALUE filters (repeatable)");
  polar->add_option("--per", po.per, "curves per: record (default) | case | an axis name");
  polar->add_option("--contour", po.contour_axis, "radial axis for a contour plot (e.g. gap)");
  polar->add_option("--unit", po.unit, "display unit of the quantity (cm, g, kN, %, ...)");
  polar->add_option("--angle-axis", po.angle_axis,
                    "the incidence-angle axis (default: found by name)");
  polar->add_option("-o,--output,--out", out,
                    "output directory (default: the database's), or a .png file (the .csv beside "
                    "it)");

  SweepPlotOptions so;
  auto* sweep_plot = app.add_subcommand(
      "sweep-plot", "a peak of a study against a swept axis, one curve per group (PNG, CSV)");
  sweep_plot->add_option("study_db", db, "the study's SQLite database")->required();
  sweep_plot->add_option("--x", so.x_axis, "the numeric swept axis along x (e.g. gap)")->required();
  sweep_plot->add_option("--y", so.output, "an output (peak) column of the study")->required();
  sweep_plot->add_option("--group", so.group_axis, "one curve per value of this axis");
  sweep_plot->add_option("--where", where,
                         "AXIS=VALUE: fixes an axis (repeatable; every other "
                         "axis must be fixed, nothing is averaged)");
  sweep_plot->add_option("--unit", so.unit, "display unit of the output (cm, g, kN, %, ...)");
  sweep_plot->add_option("--x-unit", so.x_unit, "display unit of the x axis (cm, deg, ...)");
  sweep_plot->add_option("-o,--output,--out", out,
                         "output directory (default: the database's), or a .png file (the .csv "
                         "beside it)");

  std::string pushover_dir;
  auto* pushover = app.add_subcommand(
      "pushover", "capacity curve of `isopound pushover` output (PNG), yield and capping marked");
  pushover
      ->add_option("pushover_dir", pushover_dir, "directory with pushover.csv and pushover.json")
      ->required();
  pushover->add_option("-o,--output,--out", out,
                       "a .png file, or a directory for pushover.png (default: PUSHOVER_DIR)");

  FloorSpectraArgs fa;
  auto* floor = app.add_subcommand(
      "floor-spectra", "PSA and SD spectra of every level's absolute acceleration (CSV, PNG)");
  floor->add_option("run_dir", fa.dir, "directory with histories.csv and summary.json")->required();
  quantity_option(floor->add_option("--damping", fa.damping,
                                    "damping ratio, e.g. '5 %' (default 5 %; a bare number is a "
                                    "ratio: 0.05)"),
                  {dim::kNone, "damping.ratio"}, &warnings);
  quantity_option(floor
                      ->add_option("--periods", fa.periods,
                                   "periods, e.g. 0,0.05,0.1,0.2 or '0,50 ms,0.1 s' (a bare "
                                   "number is s; default: spectra's)")
                      ->delimiter(','),
                  {dim::kTime});
  floor->add_option("--samples-per-period", fa.samples_per_period,
                    "sampling rule: history interval <= T / this (default 10)");
  floor->add_option("--short-periods", fa.short_periods,
                    "periods the history is too coarse for: refuse (exit 2) | clip (dropped, a "
                    "note); default: clip the default periods, refuse the --periods given");
  floor->add_option("--oversample", fa.oversample,
                    "sub-steps per history row for the peak (exact either way; default 1)");
  floor->add_option("--from", fa.from,
                    "steps (the run's step-accelerations.csv, output.floor_spectra: true; exact) "
                    "| rows (histories.csv); default: the steps when the run has them");
  floor->add_option("-o,--output,--out", fa.out, "output directory (default: the run directory)");
  floor->add_option("--model", fa.model, "model file (default: the one named in summary.json)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kOk : kBadInput;
  }
  for (const std::string& w : warnings)
    std::fprintf(stderr, "isopound-post: warning: %s\n", w.c_str());
  aa.timeline.fps_given = animate->count("--fps") > 0;
  // A --scale given is view.py's scale too, unless --view-scale says otherwise.
  if (animate->count("--scale") > 0 && animate->count("--view-scale") == 0)
    aa.view_scale = aa.frame.scale;
  aa.timeline.frames_per_episode_given = animate->count("--impact-frames") > 0;
  try {
    if (*spectra) return run_spectra(sa);
    if (*plot) return run_plot(run_dir, out, model);
    if (*animate) return run_animate(run_dir, out, model, aa);
    if (*polar) return run_polar(db, po, where, out);
    if (*sweep_plot) return run_sweep_plot(db, so, where, out);
    if (*pushover) return run_pushover(pushover_dir, out);
    if (*floor) return run_floor_spectra(fa);
  } catch (const BadInput& e) {
    std::fprintf(stderr, "isopound-post: error: %s\n", e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "isopound-post: error: %s\n", e.what());
    return kFailure;
  }
  return kFailure;
}
