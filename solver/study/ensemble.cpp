// Ensemble runs: members with offset initial states on a thread pool, per-peak statistics from a
// generic walk of summary.json, and the predictability horizon from the members' tracked points.
#include "solver/study/ensemble.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <stdexcept>
#include <thread>

#include "solver/io/report.h"
#include "solver/structures/contact_log.h"

namespace isopound {

Eigen::VectorXd ensemble_initial_displacement(const Model& model, int member, int members,
                                              double offset) {
  Eigen::VectorXd u0 = Eigen::VectorXd::Zero(model.size());
  if (member <= 0 || model.structures.empty() || model.structures[0].level_dofs.empty()) return u0;
  const int d = model.structures[0].has_base ? model.structures[0].base_dof()
                                             : model.structures[0].level_dofs[0];
  const bool plan = d + 1 < model.size() && model.dofs[d].kind == DofKind::kTranslationX &&
                    model.dofs[d + 1].kind == DofKind::kTranslationY;
  if (plan) {
    const double phi = 2.0 * std::numbers::pi * (member - 1) / std::max(1, members - 1);
    u0[d] = offset * std::cos(phi);
    u0[d + 1] = offset * std::sin(phi);
  } else {
    const int size = (member + 1) / 2;  // 1, 1, 2, 2, ...
    u0[d] = (member % 2 == 1 ? 1.0 : -1.0) * size * offset;
  }
  return u0;
}

double MemberStatistics::spread() const {
  // Round-off: differences below 1e-12 of the SI unit (or of the mean, if larger) are no spread,
  // e.g. the rotation of a symmetric building, ~1e-19 rad in every member.
  if (max - min <= 1e-12 * std::max(1.0, std::abs(mean))) return 0.0;
  return mean != 0.0 ? (max - min) / std::abs(mean) : INFINITY;
}

MemberStatistics member_statistics(const std::vector<double>& values) {
  MemberStatistics s;
  if (values.empty()) return s;
  s.member0 = s.min = s.max = values[0];
  double sum = 0.0;
  for (const double x : values) {
    s.min = std::min(s.min, x);
    s.max = std::max(s.max, x);
    sum += x;
  }
  const double n = static_cast<double>(values.size());
  s.mean = sum / n;
  if (values.size() > 1) {
    double squares = 0.0;
    for (const double x : values) squares += (x - s.mean) * (x - s.mean);
    s.stddev = std::sqrt(squares / (n - 1.0));
  }
  return s;
}

namespace {

using nlohmann::json;

bool is_peak(const json& j) {
  return j.is_object() && j.contains("value") && j.contains("unit") && j.contains("time_s") &&
         j["value"].is_number();
}

std::string escape_pointer_token(const std::string& token) {
  std::string out;
  for (const char c : token) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

// The readable name of a list entry: its label or name, else its index.
std::string entry_name(const json& entry, std::size_t index) {
  for (const char* key : {"label", "name"})
    if (entry.is_object() && entry.contains(key) && entry[key].is_string())
      return entry[key].get<std::string>();
  return std::to_string(index);
}

struct Found {
  std::string pointer, label, unit, name;
  std::vector<std::string> tokens;  // pointer tokens, unescaped
};

// The short name of a peak: the names of the list entries it lies in, '/'-joined (an entry
// whose name extends the previous one replaces it: "b", "b/base" -> "b/base"), then the object
// keys after the last list entry.
std::string short_name(const json& summary, const std::vector<std::string>& tokens) {
  std::string entries, keys;
  const json* j = &summary;
  for (const std::string& tok : tokens) {
    if (j->is_array()) {
      const std::string name = entry_name((*j)[std::stoul(tok)], std::stoul(tok));
      if (entries.empty() || name.rfind(entries + "/", 0) == 0)
        entries = name;
      else
        entries += "/" + name;
      keys.clear();
      j = &(*j)[std::stoul(tok)];
    } else {
      keys += (keys.empty() ? "" : " ") + tok;
      j = &(*j)[tok];
    }
  }
  return entries.empty() ? keys : entries + " " + keys;
}

void walk(const json& j, std::vector<std::string>& tokens, const std::string& pointer,
          const std::string& label, std::vector<Found>& out) {
  if (is_peak(j)) {
    out.push_back({pointer, label, j.value("unit", std::string()), "", tokens});
    return;
  }
  const auto join = [&](const std::string& name) {
    return label.empty() ? name : label + "." + name;
  };
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      tokens.push_back(key);
      walk(value, tokens, pointer + "/" + escape_pointer_token(key), join(key), out);
      tokens.pop_back();
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      tokens.push_back(std::to_string(i));
      walk(j[i], tokens, pointer + "/" + std::to_string(i), join(entry_name(j[i], i)), out);
      tokens.pop_back();
    }
  }
}

// Headline classification by position in summary.json (report.cpp, report3d.cpp and the 3D
// contact block "contacts_3d").
HeadlinePeak classify(const json& summary, const std::vector<std::string>& t) {
  const auto at = [&](std::size_t n) -> const json& {
    const json* j = &summary;
    for (std::size_t k = 0; k < n; ++k) {
      const std::string& tok = t[k];
      j = j->is_array() ? &(*j)[std::stoul(tok)] : &(*j)[tok];
    }
    return *j;
  };
  const std::size_t n = t.size();
  const bool has_3d = summary.contains("buildings_3d");
  if (t[0] == "buildings_3d" && n >= 5 && t[2] == "levels") {
    if (n == 5 && t[4] == "theta") return HeadlinePeak::kRotation;
    const bool base = at(4).value("label", std::string()) == "base";
    const bool displacement =
        (n == 7 && t[4] == "centre_of_mass" && t[5] == "displacement" && t[6] == "resultant") ||
        (n == 8 && t[4] == "corners" && t[6] == "displacement" && t[7] == "resultant");
    if (base && displacement) return HeadlinePeak::kBaseDisplacement;
  }
  if (t[0] == "buildings_3d" && n == 7 && t[2] == "storeys" && t[4] == "corner_columns" &&
      t[6] == "drift_ratio")
    return HeadlinePeak::kCornerDriftRatio;
  if (t[0] == "contacts_3d" && n == 3 && t[2] == "normal_force") return HeadlinePeak::kContactForce;
  if (!has_3d && t[0] == "structures" && n == 5) {
    if (t[2] == "levels" && t[3] == "0" && t[4] == "displacement" &&
        at(2).contains("base_displacement_m"))
      return HeadlinePeak::kBaseDisplacement;
    if (t[2] == "stories" && t[4] == "drift_ratio") return HeadlinePeak::kCornerDriftRatio;
  }
  if (!has_3d && t[0] == "elements" && n == 3 && t[2] == "peak_force" && at(2).contains("impacts"))
    return HeadlinePeak::kContactForce;
  return HeadlinePeak::kNone;
}

// The points whose separation defines the horizon: each a pair of DOF combinations (x, y).
struct TrackedPoint {
  std::string label;
  std::vector<std::pair<int, double>> x_terms, y_terms;
};

std::vector<TrackedPoint> tracked_points(const Model& model) {
  std::vector<TrackedPoint> points;
  for (const PlanProbe& p : model.probes)
    if (p.quantity == PlanProbe::Quantity::kDisplacement &&
        p.label.find("/corner ") != std::string::npos)
      points.push_back({p.label, p.x_terms, p.y_terms});
  if (!points.empty()) return points;
  // No plan corners (2D): every level of every structure, along x.
  for (const StructureInfo& s : model.structures)
    for (const int d : s.level_dofs) points.push_back({model.dofs[d].label, {{d, 1.0}}, {}});
  return points;
}

// Takes the history rows of a member: keeps time and the tracked points' (x, y) per row and
// passes the rows on to `next` (member 0's histories.csv) if any.
class PointTracker : public HistorySink {
 public:
  PointTracker(const Model& model, HistorySink* next)
      : points_(tracked_points(model)), dofs_(model.size()), next_(next) {
    if (!model.dofs.empty()) first_label_ = model.dofs[0].label + " u [";
  }
  void begin(const std::vector<std::string>& columns) override {
    // Columns: time, ground_acceleration(s), then u of every DOF (analysis.cpp).
    u_column_ = 2;
    if (columns.size() > 2 && columns[2].rfind("ground_acceleration_y", 0) == 0) u_column_ = 3;
    if (dofs_ > 0 &&
        (columns.size() < u_column_ + dofs_ || columns[u_column_].rfind(first_label_, 0) != 0))
      throw std::logic_error("ensemble: unexpected history columns");
    if (next_) next_->begin(columns);
  }
  void row(const double* values, std::size_t count) override {
    times_.push_back(values[0]);
    const double* u = values + u_column_;
    for (const TrackedPoint& p : points_) {
      double x = 0.0, y = 0.0;
      for (const auto& [d, c] : p.x_terms) x += c * u[d];
      for (const auto& [d, c] : p.y_terms) y += c * u[d];
      xy_.push_back(x);
      xy_.push_back(y);
    }
    if (next_) next_->row(values, count);
  }
  const std::vector<TrackedPoint>& points() const { return points_; }
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& xy() const { return xy_; }  // row-major, 2 per point

 private:
  std::vector<TrackedPoint> points_;
  std::size_t dofs_;
  HistorySink* next_;
  std::string first_label_;
  std::size_t u_column_ = 2;
  std::vector<double> times_, xy_;
};

struct MemberOutput {
  json summary;
  EnsembleTrack track;
  double analysed = 0.0;
  JobResult job;  // member 0 only
};

MemberOutput run_member(const ModelConfig& config, const GroundMotion& motion,
                        const GroundMotionPeaks& motion_peaks, int member,
                        const EnsembleOptions& options, HistorySink* histories,
                        std::function<void(double, double)> progress,
                        const std::string& event_log) {
  EnsembleMember run = run_ensemble_member(config, motion, member, options, histories,
                                           std::move(progress), event_log);
  JobResult job;
  job.motion = motion;
  job.motion_peaks = motion_peaks;
  job.model = std::move(run.model);
  job.analysis = std::move(run.analysis);
  job.first_impact_time = std::move(run.first_impact_time);
  MemberOutput out;
  out.summary = summary_json(config, job);
  out.track = std::move(run.track);
  out.analysed = job.analysis.stats.duration;
  if (member == 0) out.job = std::move(job);
  return out;
}

}  // namespace

EnsembleMember run_ensemble_member(const ModelConfig& config, const GroundMotion& motion,
                                   int member, const EnsembleOptions& options,
                                   HistorySink* histories,
                                   std::function<void(double, double)> progress,
                                   const std::string& event_log) {
  EnsembleMember out;
  out.model = build_model(config);
  RunOptions run = run_options(config);
  run.initial_displacement =
      ensemble_initial_displacement(out.model, member, options.members, options.offset);
  run.output.histories = true;  // the tracker needs the rows; only member 0's reach a file
  PointTracker tracker(out.model, config.output.histories ? histories : nullptr);
  run.history_sink = &tracker;
  run.progress = std::move(progress);
  ContactEventLog log(out.model, event_log);  // as run_job (job.cpp)
  if (!log.empty()) run.observer = &log;
  out.analysis = run_analysis(out.model, motion, run);
  log.close();
  out.first_impact_time = log.first_impact_times(out.model);
  out.track.times = tracker.times();
  out.track.xy = tracker.xy();
  for (const TrackedPoint& p : tracker.points()) out.track.points.push_back(p.label);
  return out;
}

Horizon predictability_horizon(const std::vector<const EnsembleTrack*>& tracks, double analysed,
                               double distance) {
  // The first output sample at which any two members' point is farther apart than `distance`
  // (all pairs: the members' own spread, not only the distance to member 0).
  Horizon h;
  h.time = analysed;
  if (tracks.empty()) return h;
  const std::size_t points = tracks[0]->points.size();
  std::size_t rows = tracks[0]->times.size();
  for (const EnsembleTrack* t : tracks) rows = std::min(rows, t->times.size());
  h.points = points;
  h.samples = rows;
  const std::size_t n = tracks.size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t p = 0; p < points; ++p) {
      const std::size_t i = 2 * (r * points + p);
      double widest = 0.0;
      for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b) {
          const double dx = tracks[a]->xy[i] - tracks[b]->xy[i];
          const double dy = tracks[a]->xy[i + 1] - tracks[b]->xy[i + 1];
          widest = std::max(widest, std::hypot(dx, dy));
        }
      h.max_separation = std::max(h.max_separation, widest);
      if (!h.reached && widest > distance) {
        h.reached = true;
        h.time = tracks[0]->times[r];
        h.point = tracks[0]->points[p];
      }
    }
  }
  return h;
}

std::vector<PeakStatistics> peak_statistics(const std::vector<json>& summaries) {
  std::vector<PeakStatistics> result;
  if (summaries.empty()) return result;
  std::vector<Found> found;
  std::vector<std::string> tokens;
  walk(summaries[0], tokens, "", "", found);
  std::vector<double> value(summaries.size()), positive(summaries.size()),
      negative(summaries.size());
  for (const Found& f : found) {
    const json::json_pointer pointer(f.pointer);
    for (std::size_t m = 0; m < summaries.size(); ++m) {
      if (!summaries[m].contains(pointer) || !is_peak(summaries[m][pointer]))
        throw std::logic_error("ensemble: member " + std::to_string(m) + " has no peak " +
                               f.pointer);
      const json& p = summaries[m][pointer];
      value[m] = p["value"].get<double>();
      positive[m] = p.value("positive", 0.0);
      negative[m] = p.value("negative", 0.0);
    }
    PeakStatistics s;
    s.pointer = f.pointer;
    s.label = f.label;
    s.name = short_name(summaries[0], f.tokens);
    s.unit = f.unit;
    s.headline = classify(summaries[0], f.tokens);
    s.value = member_statistics(value);
    s.positive = member_statistics(positive);
    s.negative = member_statistics(negative);
    result.push_back(std::move(s));
  }
  return result;
}

EnsembleResult run_ensemble(const ModelConfig& config, const EnsembleOptions& options,
                            HistorySink* member0_histories,
                            std::function<void(double, double)> progress,
                            const std::string& member0_event_log) {
  if (options.members < 1)
    throw std::invalid_argument("--ensemble: the number of members must be >= 1");
  if (options.jobs < 1) throw std::invalid_argument("-j: the number of threads must be >= 1");
  // Shared, read-only: the ground motion and the config; each member builds its own model.
  const GroundMotion motion =
      load_ground_motion(config.ground_motion, !config.structures3d.empty());
  check_step_against_record(config.analysis, motion);
  const GroundMotionPeaks motion_peaks = peaks_of(motion);

  const int n = options.members;
  std::vector<MemberOutput> outputs(n);
  std::vector<std::exception_ptr> errors(n);
  std::atomic<int> next{0};
  const auto work = [&]() {
    for (int m = next++; m < n; m = next++) {
      try {
        outputs[m] = run_member(config, motion, motion_peaks, m, options,
                                m == 0 ? member0_histories : nullptr,
                                m == 0 ? progress : std::function<void(double, double)>(),
                                m == 0 ? member0_event_log : std::string());
      } catch (...) {
        errors[m] = std::current_exception();
      }
    }
  };
  const int threads = std::min(options.jobs, n);
  if (threads <= 1) {
    work();
  } else {
    std::vector<std::thread> pool;
    for (int k = 0; k < threads; ++k) pool.emplace_back(work);
    for (std::thread& t : pool) t.join();
  }
  // Member 0 is the run as given: its failure is the run's. A later member that diverges is
  // reported and left out of the statistics (a divergence is itself a finding about the model).
  EnsembleResult result;
  for (int m = 0; m < n; ++m) {
    if (!errors[m]) continue;
    if (m == 0) std::rethrow_exception(errors[m]);
    try {
      std::rethrow_exception(errors[m]);
    } catch (const AnalysisError& e) {
      result.failed.push_back({m, e.time(), e.what()});
    }
  }

  result.members = n;
  result.offset = options.offset;
  result.horizon_distance = options.horizon_distance;
  result.analysed = outputs[0].analysed;
  std::vector<json> summaries;
  std::vector<const EnsembleTrack*> tracks;
  for (int m = 0; m < n; ++m) {
    if (errors[m]) continue;
    summaries.push_back(std::move(outputs[m].summary));
    tracks.push_back(&outputs[m].track);
  }
  result.peaks = peak_statistics(summaries);

  const Horizon h = predictability_horizon(tracks, result.analysed, options.horizon_distance);
  result.horizon = h.time;
  result.horizon_reached = h.reached;
  result.horizon_point = h.point;
  result.max_separation = h.max_separation;
  result.tracked_points = h.points;
  result.samples = h.samples;
  result.member0 = std::move(outputs[0].job);
  return result;
}

namespace {

const char* headline_name(HeadlinePeak h) {
  switch (h) {
    case HeadlinePeak::kBaseDisplacement:
      return "base_displacement";
    case HeadlinePeak::kCornerDriftRatio:
      return "corner_drift_ratio";
    case HeadlinePeak::kContactForce:
      return "contact_normal_force";
    case HeadlinePeak::kRotation:
      return "rotation";
    case HeadlinePeak::kNone:
      break;
  }
  return "";
}

json stats_json(const MemberStatistics& s) {
  return {{"member0", s.member0}, {"min", s.min},       {"mean", s.mean},
          {"max", s.max},         {"stddev", s.stddev}, {"spread", s.spread()}};
}

bool warns(const PeakStatistics& p, const EnsembleOptions& options) {
  return p.headline != HeadlinePeak::kNone && p.headline != HeadlinePeak::kRotation &&
         p.value.spread() > options.spread_warning;
}

}  // namespace

json ensemble_json(const EnsembleResult& r, const EnsembleOptions& options) {
  json peaks = json::array();
  for (const PeakStatistics& p : r.peaks) {
    json jp = {{"pointer", p.pointer}, {"label", p.label}, {"unit", p.unit}};
    if (p.headline != HeadlinePeak::kNone) jp["headline"] = headline_name(p.headline);
    jp["value"] = stats_json(p.value);
    jp["positive"] = stats_json(p.positive);
    jp["negative"] = stats_json(p.negative);
    peaks.push_back(jp);
  }
  const std::string warning = ensemble_warning(r, options);
  json failed = json::array();
  for (const FailedMember& f : r.failed)
    failed.push_back({{"member", f.member}, {"time_s", f.time}, {"error", f.error}});
  return {{"members", r.members},
          {"members_in_statistics", r.members - static_cast<int>(r.failed.size())},
          {"failed_members", failed},
          {"offset_m", r.offset},
          {"offset_rule",
           "member 0 as given; member k > 0 starts with the lowest level of the first structure "
           "(base slab, or first floor of a fixed base) displaced by offset_m: in plan (3D) along "
           "the angle 2 pi (k - 1) / (members - 1) from +x, counter-clockwise; in 2D along x by "
           "+1, -1, +2, -2, ... times offset_m; zero velocity, equilibrium acceleration"},
          {"horizon_s", r.horizon},
          {"horizon_reached", r.horizon_reached},
          {"horizon_distance_m", r.horizon_distance},
          {"horizon_point", r.horizon_point},
          {"horizon_note",
           r.horizon_reached
               ? "the first output time at which two members' tracked points (3D: slab corners; "
                 "2D: levels) were farther apart than horizon_distance_m"
               : "no two members' tracked points ever differed by horizon_distance_m: horizon_s is "
                 "the analysed length of the record"},
          {"analysed_s", r.analysed},
          {"max_separation_m", r.max_separation},
          {"tracked_points", r.tracked_points},
          {"samples_compared", r.samples},
          {"statistics_note",
           "per peak of summary.json (pointer into it): member 0's value and the members' min, "
           "mean, max, sample standard deviation (N - 1) and spread = (max - min) / |mean| (0 "
           "when max - min <= 1e-12 max(1, |mean|) in SI units: round-off)"},
          {"spread_warning", warning.empty() ? json(nullptr) : json(warning)},
          {"peaks", peaks}};
}

void write_summary_with_ensemble(const std::string& path, const ModelConfig& config,
                                 const JobResult& member0, const UnobstructedResult* unobstructed,
                                 const EnsembleResult& result, const EnsembleOptions& options) {
  json j = summary_json(config, member0, unobstructed);
  j["ensemble"] = ensemble_json(result, options);
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << std::setw(2) << j << '\n';
  if (!out) throw std::runtime_error("error writing " + path);
}

void write_ensemble_csv(const std::string& path, const EnsembleResult& r) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  std::fprintf(f, "peak,pointer,field,unit,headline,member0,min,mean,max,stddev,spread [-]\n");
  const auto quoted = [](const std::string& s) {
    std::string q = "\"";
    for (const char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  for (const PeakStatistics& p : r.peaks)
    for (const auto& [field, s] :
         {std::pair<const char*, const MemberStatistics&>{"value", p.value},
          {"positive", p.positive},
          {"negative", p.negative}})
      std::fprintf(f, "%s,%s,%s,%s,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", quoted(p.label).c_str(),
                   quoted(p.pointer).c_str(), field, p.unit.c_str(), headline_name(p.headline),
                   s.member0, s.min, s.mean, s.max, s.stddev, s.spread());
  if (std::fclose(f) != 0) throw std::runtime_error("error writing " + path);
}

std::string ensemble_warning(const EnsembleResult& r, const EnsembleOptions& options) {
  const PeakStatistics* worst = nullptr;
  int count = 0;
  for (const PeakStatistics& p : r.peaks)
    if (warns(p, options)) {
      ++count;
      if (!worst || p.value.spread() > worst->value.spread()) worst = &p;
    }
  if (!worst) return "";
  char line[512];
  std::snprintf(line, sizeof line,
                "warning: %d headline peak%s spread more than %.0f %% across the %d members "
                "(largest: %s, %.1f %%): the ensemble statistics, not the single run, are the "
                "result",
                count, count == 1 ? "" : "s", 100 * options.spread_warning,
                r.members - static_cast<int>(r.failed.size()), worst->name.c_str(),
                100 * worst->value.spread());
  return line;
}

void print_ensemble(std::ostream& out, const EnsembleResult& r, const EnsembleOptions& options) {
  char line[512];
  std::snprintf(line, sizeof line,
                "Ensemble of %d members (offset %.3g um of the first structure's lowest level):\n",
                r.members, 1e6 * r.offset);
  out << line;
  int width = 4;
  for (const PeakStatistics& p : r.peaks)
    if (p.headline != HeadlinePeak::kNone) width = std::max(width, static_cast<int>(p.name.size()));
  width = std::min(width, 64);
  std::snprintf(line, sizeof line, "  %-*s %-4s %11s %11s %11s %11s %9s %9s\n", width, "peak",
                "unit", "member 0", "min", "mean", "max", "std", "spread");
  out << line;
  for (const PeakStatistics& p : r.peaks) {
    if (p.headline == HeadlinePeak::kNone) continue;
    std::string name = p.name;
    if (static_cast<int>(name.size()) > width) name = "..." + name.substr(name.size() - width + 3);
    const MemberStatistics& s = p.value;
    std::snprintf(line, sizeof line, "  %-*s %-4s %11.5g %11.5g %11.5g %11.5g %9.3g %9.2e\n", width,
                  name.c_str(), p.unit.c_str(), s.member0, s.min, s.mean, s.max, s.stddev,
                  s.spread());
    out << line;
  }
  out << "  (spread = (max - min) / |mean|; every peak of summary.json is in ensemble.csv)\n";
  if (r.horizon_reached)
    std::snprintf(line, sizeof line,
                  "  predictability horizon %.4g s: first time two members differ by more than "
                  "%.3g mm (at %s)\n",
                  r.horizon, 1e3 * r.horizon_distance, r.horizon_point.c_str());
  else
    std::snprintf(line, sizeof line,
                  "  predictability horizon %.4g s = the analysed length: no two members ever "
                  "differ by %.3g mm (largest difference %.3g mm)\n",
                  r.horizon, 1e3 * r.horizon_distance, 1e3 * r.max_separation);
  out << line;
  for (const FailedMember& f : r.failed) {
    std::snprintf(line, sizeof line,
                  "warning: member %d diverged at t = %.6g s and is left out of the statistics "
                  "and the horizon (%d of %d members used)\n",
                  f.member, f.time, r.members - static_cast<int>(r.failed.size()), r.members);
    out << line;
  }
  const std::string warning = ensemble_warning(r, options);
  if (!warning.empty()) out << warning << '\n';
}

}  // namespace isopound
