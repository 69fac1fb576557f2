// Convergence battery of the 2D contact handling (issue 8): default adaptive stepping against a
// fixed-step reference, per record x gap x impact law, walls on both sides of the base slab.
//
// The model is the thesis 3-storey building of chapter 4 (Bouc-Wen, Tb 2 s, Q/W 5 %, uy 1 cm;
// 340/340/340/250 t; 600 MN/m; rigid walls of 500 t, e = 0.7, k = k_h = 2.5e9 SI). Each case
// compares every peak (displacement, absolute acceleration per level, drift per story, wall
// force) as |p - p_ref| / p_ref and the number of impacts with an approach rate >= 1 mm/s
// (Contact1D::counted_impacts). References are cached (one file per case and step) so a rerun
// of the defaults costs only the default runs. Exit code 1 if a case breaks the acceptance
// bounds (--max-error, equal counts), 2 on bad arguments, 77 if the records are absent (a skip,
// unless ISOPOUND_REQUIRE_SHARED is set).
//
// Usage: isopound_battery [--records a,b|all] [--gaps 5,10,..(cm)] [--laws l1,l2|all]
//          [--duration s] [--reference-dt s] [--halving] [--cache dir] [--max-error f]
//          [--tolerance f] [--steps-per-contact n] [--max-step s] [--records-dir dir]
//          [--table file.md]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "solver/core/analysis.h"
#include "solver/elements/contact.h"
#include "solver/excitation/ground_motion.h"
#include "solver/materials/impact_law.h"
#include "solver/structures/building2d.h"
#include "solver/structures/pounding2d.h"

namespace {

using namespace isopound;
namespace fs = std::filesystem;

struct Options {
  std::vector<std::string> records;  // file names in records_dir
  std::vector<double> gaps = {0.05, 0.10, 0.15, 0.20, 0.30};
  std::vector<std::string> laws;
  double duration = 0.0;  // s; 0 = the whole record
  double reference_dt = 5e-6;
  bool halving = false;  // also a reference at reference_dt / 2, to show it converged
  std::string cache;     // empty: no cache
  double max_error = 0.01;
  double tolerance = 0.0;          // 0: the default of AnalysisConfig
  double steps_per_contact = 0.0;  // 0: the default
  double max_step = 0.0;           // 0: the default (adaptive dt)
  fs::path records_dir;
  std::string table;
};

// Peaks of one run, in a fixed order, with names; plus impact counts and cost.
struct Outcome {
  std::vector<double> peaks;
  std::vector<std::string> names;
  std::vector<int> counted_impacts;  // per wall
  long steps = 0;
  double seconds = 0.0;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

BuildingConfig building_with_walls(const std::string& law, double gap) {
  BuildingConfig b;
  b.name = "b";
  b.base_mass = 340e3;
  b.floors = {{340e3, 600e6, 3.2}, {340e3, 600e6, 3.2}, {250e3, 600e6, 3.2}};
  b.isolator.model = IsolatorConfig::Model::kBoucWen;
  WallConfig w;
  w.gap_left = w.gap_right = gap;
  w.impact.law = law;
  w.impact.k = 2.5e9;
  w.impact.k_h = 2.5e9;
  w.impact.e = 0.7;
  w.mass = 500e3;
  b.walls = {w};
  return b;
}

// Knobs of the default run (0: the default of AnalysisConfig).
struct Knobs {
  double tolerance = 0.0, steps_per_contact = 0.0, max_step = 0.0;
};

Outcome run_case(const GroundMotion& motion, const std::string& law, double gap, double fixed_dt,
                 const Knobs& knobs) {
  const BuildingConfig building = building_with_walls(law, gap);
  RunOptions options;
  options.output.histories = false;
  if (knobs.tolerance > 0) options.analysis.tolerance = knobs.tolerance;
  if (knobs.steps_per_contact > 0) options.analysis.steps_per_contact = knobs.steps_per_contact;
  if (knobs.max_step > 0) options.analysis.dt = knobs.max_step;
  if (fixed_dt > 0) {
    options.analysis.stepping = AnalysisConfig::Stepping::kFixed;
    options.analysis.dt = fixed_dt;
  }
  Model model = make_model(building);
  add_walls(model, 0, building, options.analysis.steps_per_contact);
  const auto start = std::chrono::steady_clock::now();
  const AnalysisResult r = run_analysis(model, motion, options);
  Outcome o;
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  o.steps = r.stats.steps + r.stats.rejected_steps;
  for (int i = 0; i < model.size(); ++i) {
    o.names.push_back("u " + model.dofs[i].label);
    o.peaks.push_back(r.displacement[i].value);
    o.names.push_back("a_abs " + model.dofs[i].label);
    o.peaks.push_back(r.absolute_acceleration[i].value);
  }
  for (std::size_t s = 0; s < r.stories.size(); ++s) {
    o.names.push_back("drift " + r.stories[s].label);
    o.peaks.push_back(r.drift[s].value);
  }
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const auto* contact = dynamic_cast<const Contact1D*>(model.elements[e].get());
    if (!contact) continue;
    o.names.push_back("F " + contact->label());
    o.peaks.push_back(r.element_outputs[e][0].value);
    o.counted_impacts.push_back(contact->counted_impacts());
  }
  return o;
}

std::string cache_file(const Options& opt, const std::string& record, double gap,
                       const std::string& law, double dt) {
  char name[512];
  std::snprintf(name, sizeof name, "%s_gap%.3f_%s_dt%.3g_dur%.3f.txt",
                fs::path(record).stem().string().c_str(), gap, law.c_str(), dt, opt.duration);
  return (fs::path(opt.cache) / name).string();
}

bool load(const std::string& path, Outcome& o) {
  std::ifstream in(path);
  if (!in) return false;
  std::size_t n_peaks = 0, n_walls = 0;
  if (!(in >> o.steps >> o.seconds >> n_peaks >> n_walls)) return false;
  o.peaks.resize(n_peaks);
  o.counted_impacts.resize(n_walls);
  for (double& p : o.peaks) in >> p;
  for (int& c : o.counted_impacts) in >> c;
  return static_cast<bool>(in);
}

void save(const std::string& path, const Outcome& o) {
  std::ofstream out(path + ".tmp");
  out.precision(17);
  out << o.steps << ' ' << o.seconds << ' ' << o.peaks.size() << ' ' << o.counted_impacts.size()
      << '\n';
  for (double p : o.peaks) out << p << '\n';
  for (int c : o.counted_impacts) out << c << '\n';
  out.close();
  fs::rename(path + ".tmp", path);
}

Outcome reference(const Options& opt, const GroundMotion& motion, const std::string& record,
                  const std::string& law, double gap, double dt) {
  Outcome o;
  const std::string path = opt.cache.empty() ? "" : cache_file(opt, record, gap, law, dt);
  if (!path.empty() && load(path, o)) return o;
  o = run_case(motion, law, gap, dt, Knobs{});
  if (!path.empty()) save(path, o);
  return o;
}

// Largest relative difference of b's peaks from a's; `which` gets the index.
double worst_error(const Outcome& ref, const Outcome& b, int& which) {
  double worst = 0.0;
  which = -1;
  for (std::size_t k = 0; k < ref.peaks.size(); ++k) {
    const double scale = std::abs(ref.peaks[k]);
    double err;
    if (scale == 0.0)
      err = b.peaks[k] == 0.0 ? 0.0 : INFINITY;  // e.g. a wall force where ref has no impact
    else
      err = std::abs(b.peaks[k] - ref.peaks[k]) / scale;
    if (err > worst || which < 0) {
      worst = err;
      which = static_cast<int>(k);
    }
  }
  return worst;
}

int count_difference(const Outcome& a, const Outcome& b) {
  int d = 0;
  for (std::size_t k = 0; k < a.counted_impacts.size(); ++k)
    d += std::abs(a.counted_impacts[k] - b.counted_impacts[k]);
  return d;
}

double number(const std::string& s, const char* what) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end != '\0' || !std::isfinite(v)) {
    std::cerr << "isopound_battery: " << what << " '" << s << "' is not a number\n";
    std::exit(2);
  }
  return v;
}

Options parse(int argc, char** argv) {
  Options opt;
  const char* env = std::getenv("ISOPOUND_SHARED");
  opt.records_dir =
      env ? fs::path(env) / "records" : fs::path(ISOPOUND_SOURCE_DIR) / ".." / "shared" / "records";
  std::string records = "all", laws = "all";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "isopound_battery: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--records") {
      records = value();
    } else if (a == "--laws") {
      laws = value();
    } else if (a == "--gaps") {
      opt.gaps.clear();
      for (const std::string& g : split(value())) opt.gaps.push_back(number(g, "gap") / 100.0);
    } else if (a == "--duration") {
      opt.duration = number(value(), "duration");
    } else if (a == "--reference-dt") {
      opt.reference_dt = number(value(), "reference-dt");
    } else if (a == "--halving") {
      opt.halving = true;
    } else if (a == "--cache") {
      opt.cache = value();
    } else if (a == "--max-error") {
      opt.max_error = number(value(), "max-error");
    } else if (a == "--tolerance") {
      opt.tolerance = number(value(), "tolerance");
    } else if (a == "--steps-per-contact") {
      opt.steps_per_contact = number(value(), "steps-per-contact");
    } else if (a == "--max-step") {
      opt.max_step = number(value(), "max-step");
    } else if (a == "--records-dir") {
      opt.records_dir = value();
    } else if (a == "--table") {
      opt.table = value();
    } else {
      std::cerr << "isopound_battery: unknown option '" << a << "'\n";
      std::exit(2);
    }
  }
  if (!fs::exists(opt.records_dir)) {
    // As the test suite does (tests/test_support.h): skip (77, ctest's SKIP_RETURN_CODE) unless
    // ISOPOUND_REQUIRE_SHARED asks for the records.
    const char* required = std::getenv("ISOPOUND_REQUIRE_SHARED");
    const bool must = required && std::string(required) != "" && std::string(required) != "0";
    std::cerr << "isopound_battery: records folder absent: " << opt.records_dir << "\n";
    std::exit(must ? 2 : 77);
  }
  if (records == "all") {
    for (const auto& entry : fs::directory_iterator(opt.records_dir))
      if (entry.path().extension() == ".AT2") opt.records.push_back(entry.path().filename());
    std::sort(opt.records.begin(), opt.records.end());
  } else {
    for (const std::string& r : split(records))
      opt.records.push_back(fs::path(r).extension() == ".AT2" ? r : r + ".AT2");
  }
  if (laws == "all") {
    for (std::string_view l : impact_law_names()) opt.laws.emplace_back(l);
  } else {
    opt.laws = split(laws);
  }
  if (!opt.cache.empty()) fs::create_directories(opt.cache);
  return opt;
}

}  // namespace

int main(int argc, char** argv) {
  const Options opt = parse(argc, argv);
  std::ostringstream table;
  table << "| record | gap cm | law | worst peak error | worst peak | impacts ref/default | steps "
           "default | steps ref | s default | s ref |"
        << (opt.halving ? " ref vs ref/2 |" : "") << "\n|---|---|---|---|---|---|---|---|---|---|"
        << (opt.halving ? "---|" : "") << "\n";
  std::vector<double> worst_all;
  int failures = 0, count_mismatches = 0, impacting = 0;
  long steps_default = 0, steps_ref = 0;
  double seconds_default = 0.0, seconds_ref = 0.0, worst_halving = 0.0;
  std::printf("record\tgap\tlaw\tworst\tpeak\timpacts_ref\timpacts\tsteps\tsteps_ref\ts\ts_ref%s\n",
              opt.halving ? "\thalving" : "");
  for (const std::string& record : opt.records) {
    GroundMotion motion = read_record((opt.records_dir / record).string());
    if (opt.duration > 0) {
      const auto n = static_cast<std::size_t>(std::llround(opt.duration / motion.dt)) + 1;
      if (n < motion.acceleration.size()) motion.acceleration.resize(n);
    }
    for (const double gap : opt.gaps) {
      for (const std::string& law : opt.laws) {
        const Outcome ref = reference(opt, motion, record, law, gap, opt.reference_dt);
        const Outcome def =
            run_case(motion, law, gap, 0.0, {opt.tolerance, opt.steps_per_contact, opt.max_step});
        int which = 0;
        const double worst = worst_error(ref, def, which);
        const int dcount = count_difference(ref, def);
        int n_ref = 0, n_def = 0;
        for (int c : ref.counted_impacts) n_ref += c;
        for (int c : def.counted_impacts) n_def += c;
        double halving = 0.0;
        if (opt.halving) {
          const Outcome fine = reference(opt, motion, record, law, gap, opt.reference_dt / 2);
          int w = 0;
          halving = worst_error(fine, ref, w);
          if (count_difference(fine, ref) != 0) halving = INFINITY;
          worst_halving = std::max(worst_halving, halving);
        }
        worst_all.push_back(worst);
        if (n_ref > 0) ++impacting;
        if (dcount != 0) ++count_mismatches;
        if (worst > opt.max_error || dcount != 0) ++failures;
        steps_default += def.steps;
        steps_ref += ref.steps;
        seconds_default += def.seconds;
        seconds_ref += ref.seconds;
        const std::string stem = fs::path(record).stem().string();
        std::printf("%s\t%.0f\t%s\t%.3e\t%s\t%d\t%d\t%ld\t%ld\t%.3f\t%.2f", stem.c_str(), gap * 100,
                    law.c_str(), worst, def.names[which].c_str(), n_ref, n_def, def.steps,
                    ref.steps, def.seconds, ref.seconds);
        if (opt.halving) std::printf("\t%.2e", halving);
        std::printf("\n");
        std::fflush(stdout);
        char row[512];
        std::snprintf(row, sizeof row,
                      "| %s | %.0f | %s | %.3f %% | %s | %d / %d | %ld | %ld | %.3f | %.1f |",
                      stem.c_str(), gap * 100, law.c_str(), 100 * worst, def.names[which].c_str(),
                      n_ref, n_def, def.steps, ref.steps, def.seconds, ref.seconds);
        table << row;
        if (opt.halving) {
          std::snprintf(row, sizeof row, " %.1e |", halving);
          table << row;
        }
        table << "\n";
      }
    }
  }
  std::vector<double> sorted = worst_all;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  const double worst = sorted.empty() ? 0.0 : sorted.back();
  std::ostringstream summary;
  summary << worst_all.size() << " cases (" << impacting << " with impacts >= 1 mm/s in the "
          << "reference): median worst-peak error " << 100 * median << " %, worst " << 100 * worst
          << " %, impact-count mismatches " << count_mismatches << ", cases failing (> "
          << 100 * opt.max_error << " % or count) " << failures << "; steps default "
          << steps_default << " vs reference " << steps_ref << " (" << opt.reference_dt
          << " s); CPU s default " << seconds_default << ", reference (this run or cached) "
          << seconds_ref;
  if (opt.halving) summary << "; reference vs half step: worst " << worst_halving;
  std::printf("# %s\n", summary.str().c_str());
  if (!opt.table.empty()) {
    std::ofstream out(opt.table);
    out << table.str() << "\n" << summary.str() << "\n";
  }
  return failures == 0 ? 0 : 1;
}
