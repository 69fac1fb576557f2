// Time-history analysis driver: walks the record interval by interval; inside an interval the
// step is halved where the local error estimate says so (steps stay aligned with the samples).
#include "solver/core/analysis.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "solver/core/compressed_rows.h"
#include "solver/core/constants.h"
#include "solver/core/modes.h"
#include "solver/core/newmark.h"
#include "solver/core/probe_record.h"

namespace isopound {

std::vector<Story> stories_of(const Model& model) {
  std::vector<Story> stories;
  for (const StructureInfo& s : model.structures) {
    // Story k links floor k and the level below it (the ground, a floor or the isolated slab);
    // the isolation layer is the isolator, no story. A structure with no story heights (e.g. a
    // moat-wall oscillator) has no stories.
    for (std::size_t k = 0; k < s.story_heights.size(); ++k) {
      const int floor = static_cast<int>(k) + 1;
      const int below = s.below_floor_level(floor);
      Story story;
      story.label = s.name + "/story " + std::to_string(k + 1);
      story.upper = s.level_dofs[static_cast<std::size_t>(s.floor_level(floor))];
      story.lower = below < 0 ? -1 : s.level_dofs[static_cast<std::size_t>(below)];
      story.height = s.story_heights[k];
      stories.push_back(story);
    }
  }
  return stories;
}

namespace {

// Keeps the rows in AnalysisResult::history when no sink is given.
class MemoryHistory : public HistorySink {
 public:
  explicit MemoryHistory(History& history) : history_(history) {}
  void begin(const std::vector<std::string>& columns) override { history_.columns = columns; }
  void row(const double* values, std::size_t count) override {
    history_.values.insert(history_.values.end(), values, values + count);
  }

 private:
  History& history_;
};

// Ground acceleration (both components) at a fraction `frac` in [0, 1] of analysis interval
// `interval`.
struct GroundSampler {
  const GroundMotion& motion;
  int per_sample;  // analysis intervals per record interval
  // per_sample = 2^shift (else shift = -1): a step's sample then takes no division, the
  // fraction multiplied by 2^-shift (exact: x / 2^k and x 2^-k are the same real number, rounded
  // the same way), the interval split by shifts (intervals are >= 0).
  int shift = std::has_single_bit(static_cast<unsigned>(per_sample))
                  ? std::countr_zero(static_cast<unsigned>(per_sample))
                  : -1;
  double exact_inverse = shift >= 0 ? 1.0 / per_sample : 0.0;

  GroundAcceleration operator()(long interval, double frac_of_interval) const {
    long k = shift >= 0 ? interval >> shift : interval / per_sample;
    const long j = shift >= 0 ? interval & (per_sample - 1) : interval % per_sample;
    const double within = static_cast<double>(j) + frac_of_interval;
    double frac = exact_inverse > 0 ? within * exact_inverse : within / per_sample;
    if (frac >= 1.0) {
      ++k;
      frac = 0.0;
    }
    const auto sample = [&](const std::vector<double>& a) {
      const long n = static_cast<long>(a.size());
      const double a0 = k < n ? a[k] : 0.0;
      const double a1 = k + 1 < n ? a[k + 1] : 0.0;
      return a0 + frac * (a1 - a0);
    };
    return {sample(motion.acceleration), sample(motion.acceleration_y)};
  }
};

std::string divergence_message(const Model& model, const NewmarkStepper& stepper, double t,
                               double h, int iterations, int& dof) {
  const Eigen::VectorXd& u = stepper.trial_u();
  const Eigen::VectorXd& r = stepper.residual();
  dof = 0;
  bool nonfinite = false;
  for (int i = 0; i < u.size(); ++i) {
    if (!std::isfinite(u[i]) || !std::isfinite(r[i])) {
      dof = i;
      nonfinite = true;
      break;
    }
  }
  if (!nonfinite) r.cwiseAbs().maxCoeff(&dof);
  std::ostringstream msg;
  msg << "analysis diverged at t = " << t << " s, DOF '" << model.dofs[dof].label << "': ";
  if (nonfinite)
    msg << "displacement or force became NaN/inf";
  else
    msg << "Newton did not converge in " << iterations << " iterations at step " << h
        << " s (residual " << std::abs(r[dof]) << " N, displacement " << u[dof] << " m)";
  msg << ". Hint: check units of masses and stiffnesses, the isolator parameters (Tb, QW, uy), "
         "or allow more halvings (analysis.max_halvings) / iterations.";
  return msg.str();
}

// A history row at time t inside a step from row `start` to row `end` (column 0: time; u of the
// `dofs` DOFs from column first_u, their v right after). Newmark average acceleration (gamma 1/2,
// beta 1/4) holds the acceleration at (a0 + a1) / 2 over the step, so v is linear in time and
// u(t0 + tau) = u0 + tau (v0 + v(tau)) / 2, which is u1 at tau = h; the other columns (ground,
// accelerations, forces) are interpolated linearly, but for the columns marked `held` (counts and
// 0/1 states, Element::OutputKind), which change only where a step ends and keep their value at
// the step's start.
void history_row_between(const std::vector<double>& start, const std::vector<double>& end,
                         const std::vector<char>& held, std::size_t first_u, int dofs, double t,
                         std::vector<double>& out) {
  const double tau = t - start[0];
  const double s = tau / (end[0] - start[0]);
  for (std::size_t c = 0; c < end.size(); ++c)
    out[c] = held[c] ? start[c] : start[c] + s * (end[c] - start[c]);
  out[0] = t;
  const std::size_t first_v = first_u + static_cast<std::size_t>(dofs);
  for (std::size_t i = 0; i < static_cast<std::size_t>(dofs); ++i)
    out[first_u + i] = start[first_u + i] + 0.5 * tau * (start[first_v + i] + out[first_v + i]);
}

}  // namespace

double shortest_period(Model& model) {
  return max_step_period(model, AnalysisConfig::MaxStepRule::kAllModes, 0.0);
}

Eigen::MatrixXd stiffness_at_rest(Model& model, int excluded) {
  Eigen::MatrixXd k = model.stiffness;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.size());
  for (std::size_t i = 0; i < model.elements.size(); ++i) {
    if (static_cast<int>(i) == excluded) continue;
    Element& e = *model.elements[i];
    e.set_trial(zero, zero);
    e.add_tangent(k, 0.0);
    e.revert();
  }
  return k;
}

double max_step_period(Model& model, AnalysisConfig::MaxStepRule rule, double threshold) {
  const int n = model.size();
  const Eigen::MatrixXd k = stiffness_at_rest(model);
  Modes modes;
  try {
    modes = compute_modes(k, model.mass, model.influence);
  } catch (const std::invalid_argument&) {
    return 0.0;  // a mechanism at rest (e.g. only contacts hold a DOF): no period rule
  }
  if (rule == AnalysisConfig::MaxStepRule::kAllModes) return modes.period.minCoeff();
  // Effective mass ratio of each mode along each ground direction that moves mass; a mode
  // counts if either ratio reaches the threshold. The ratios of one direction sum to 1, so
  // at least one mode (the first of them) always counts.
  Eigen::VectorXd ratio = modes.effective_mass_ratio;
  if (model.influence_y.size() == n) {
    const Eigen::VectorXd m_iota_y = model.mass * model.influence_y;
    const double total_y = model.influence_y.dot(m_iota_y);
    if (total_y > 0)
      ratio = ratio.cwiseMax((modes.shape.transpose() * m_iota_y).cwiseAbs2() / total_y);
  }
  double period = 0.0;
  for (int j = 0; j < n; ++j)
    if (ratio[j] >= threshold && (period == 0.0 || modes.period[j] < period))
      period = modes.period[j];
  return period > 0.0 ? period : modes.period.minCoeff();
}

AnalysisResult run_analysis(Model& model, const GroundMotion& motion, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  const AnalysisConfig& cfg = options.analysis;
  const int n = model.size();
  const int n_elements = static_cast<int>(model.elements.size());
  if (motion.acceleration.size() < 2 || !(motion.dt > 0))
    throw std::invalid_argument("ground motion '" + motion.name + "' has fewer than 2 samples");

  AnalysisResult res;
  res.stories = stories_of(model);
  res.displacement.resize(n);
  res.velocity.resize(n);
  res.absolute_acceleration.resize(n);
  res.drift.resize(res.stories.size());
  res.drift_ratio.resize(res.stories.size());
  res.probes.resize(model.probes.size());
  res.element_outputs.resize(n_elements);
  res.tracked.resize(options.tracked.size());
  res.story_shear.resize(res.stories.size());
  res.base_shear.resize(model.structures.size());
  res.base_shear_y.resize(model.structures.size());
  res.base_shear_resultant.resize(model.structures.size());
  // Levels above each story (same order as stories_of) and the levels from the isolated slab
  // up (x, and y in plan) of each isolated structure: the shears are sums over them.
  std::vector<std::vector<int>> above_story, above_base(model.structures.size()),
      above_base_y(model.structures.size());
  for (std::size_t s = 0; s < model.structures.size(); ++s) {
    const StructureInfo& info = model.structures[s];
    for (std::size_t k = 0; k < info.story_heights.size(); ++k)
      above_story.emplace_back(info.level_dofs.begin() + info.floor_level(static_cast<int>(k) + 1),
                               info.level_dofs.end());
    if (!info.has_base) continue;
    above_base[s].assign(info.level_dofs.begin() + info.base_level, info.level_dofs.end());
    if (!info.level_dofs_y.empty())
      above_base_y[s].assign(info.level_dofs_y.begin() + info.base_level, info.level_dofs_y.end());
  }
  CompressedRows mass_rows;  // M, for M a_abs
  mass_rows.assign(model.mass);
  Eigen::VectorXd inertia(n);     // M a_abs
  Eigen::VectorXd base_force(n);  // the isolator's and the base-level contacts' forces
  std::vector<double> story_shear_now(above_story.size()), base_shear_now(above_base.size()),
      base_shear_y_now(above_base.size());
  for (int e = 0; e < n_elements; ++e)
    res.element_outputs[e].resize(model.elements[e]->output_count());

  NewmarkStepper stepper(model, {cfg.newton_tolerance, cfg.max_iterations, cfg.block_elimination});

  // Analysis interval H divides the record interval so that H <= the largest step.
  const bool adaptive = cfg.stepping == AnalysisConfig::Stepping::kAdaptive;
  double max_step = cfg.dt;
  if (adaptive && max_step <= 0 && cfg.steps_per_period > 0) {
    res.stats.step_period = max_step_period(model, cfg.max_step_rule, cfg.participation_threshold);
    max_step = res.stats.step_period / cfg.steps_per_period;
  }
  int per_sample = 1;
  if (max_step > 0)
    per_sample = std::max(1, static_cast<int>(std::ceil(motion.dt / max_step - 1e-9)));
  const double H = motion.dt / per_sample;
  double total = motion.duration() + options.extra_time;
  res.stats.record_end = total;
  res.stats.t_end = cfg.t_end;
  if (cfg.t_end > 0) total = std::min(total, cfg.t_end);
  const long intervals = static_cast<long>(std::ceil(total / H - 1e-9));
  const int max_level = cfg.max_halvings;
  stepper.reserve_step_sizes(max_level + 1);
  const GroundSampler ground{motion, per_sample};
  const bool two_components = !motion.acceleration_y.empty();
  // Absolute acceleration = relative + rigid response to the ground: a + iota a_g.
  const bool has_y = model.influence_y.size() == n;
  const auto rigid = [&](int i, const GroundAcceleration& ag) {
    return has_y && ag.y != 0.0 ? model.influence[i] * ag.x + model.influence_y[i] * ag.y
                                : model.influence[i] * ag.x;
  };

  // Error scale per DOF: the weight of the DOF's mass times the tolerance (see newmark.h); for a
  // rotation measured through a length r (Dof::length, e.g. the radius of gyration, M_ii = m r^2)
  // the moment of the weight at arm r, M_ii g / r.
  Eigen::VectorXd force_scale(n);
  for (int i = 0; i < n; ++i)
    force_scale[i] =
        cfg.tolerance * kGravity * std::max(model.mass(i, i), 1e-12) / model.dofs[i].length;

  // History layout. Row k is at exactly k * out_interval (never an accumulated sum). A step
  // ending within a millionth of a step of k * out_interval writes its own state there; a grid
  // time inside a step (an interval that is not a multiple of the step) is sampled from the
  // step's Newmark solution (history_row_between).
  const double out_interval = options.output.interval > 0 ? options.output.interval : motion.dt;
  MemoryHistory memory_history(res.history);
  HistorySink* const sink = options.output.histories
                                ? (options.history_sink ? options.history_sink : &memory_history)
                                : nullptr;
  std::vector<double> row, previous_row, sampled_row;  // this step's, the last step's, a grid row
  std::vector<char> held_column;                       // counts and states (history_row_between)
  const std::size_t first_u_column = two_components ? 3 : 2;
  HistorySink* const step_sink = options.step_sink;
  if (sink || step_sink) {
    std::vector<std::string> c = {"time [s]", "ground_acceleration [m/s2]"};
    if (two_components) c.push_back("ground_acceleration_y [m/s2]");
    const auto unit = [](const Dof& d, const char* translation, const char* rotation) {
      return d.kind == DofKind::kRotation ? rotation : translation;
    };
    for (const Dof& d : model.dofs) c.push_back(d.label + " u [" + unit(d, "m", "rad") + "]");
    for (const Dof& d : model.dofs) c.push_back(d.label + " v [" + unit(d, "m/s", "rad/s") + "]");
    for (const Dof& d : model.dofs)
      c.push_back(d.label + " a_abs [" + unit(d, "m/s2", "rad/s2") + "]");
    held_column.assign(c.size(), 0);  // time, ground, u, v, a_abs
    for (const auto& e : model.elements)
      for (int k = 0; k < e->output_count(); ++k) {
        held_column.push_back(e->output_kind(k) != Element::OutputKind::kContinuous);
        c.push_back(e->label() + " " + e->output_name(k) + " [" + e->output_unit(k) + "]");
      }
    for (std::size_t s = 0; s < model.structures.size(); ++s) {
      if (!model.structures[s].has_base) continue;
      c.push_back(model.structures[s].name + " base_shear [N]");
      if (!model.structures[s].level_dofs_y.empty())
        c.push_back(model.structures[s].name + " base_shear_y [N]");
    }
    for (const Story& st : res.stories) c.push_back(st.label + " shear [N]");
    held_column.resize(c.size(), 0);  // base and storey shears
    row.resize(c.size());
    previous_row.resize(c.size());
    sampled_row.resize(c.size());
    if (sink) sink->begin(c);
    if (step_sink) step_sink->begin(c);
  }
  long next_row = 0;  // index of the next output time, next_row * out_interval
  const double grid_tolerance = 1e-6 * H;
  long progress_tick = 0;

  // Element outputs of the current step, one element after the other.
  int outputs_total = 0;
  for (const auto& e : model.elements) outputs_total += e->output_count();
  std::vector<double> output_scratch(outputs_total);
  const auto bands_of = [](std::vector<Peak>& peaks) {
    std::vector<Peak*> pointers;
    for (Peak& peak : peaks) pointers.push_back(&peak);
    return PeakBands(std::move(pointers));
  };
  PeakBands displacement_peaks = bands_of(res.displacement);
  PeakBands velocity_peaks = bands_of(res.velocity);
  PeakBands acceleration_peaks = bands_of(res.absolute_acceleration);

  // Energy terms (trapezoidal rule on the powers).
  Eigen::VectorXd work(n);
  const Eigen::MatrixXd m_iota = model.ground_load_matrix();
  double p_in_prev = 0.0, p_visc_prev = 0.0, p_elem_prev = 0.0;
  double e_in = 0.0, e_visc = 0.0, w_elem = 0.0, max_in = 0.0, max_err = 0.0;
  double initial_energy = -1.0;  // kinetic + recoverable energy of the initial conditions
  double stored_at_start = 0.0;  // element work is counted from 0, their energy from here

  ProbeRecorder probe_recorder(model.probes);

  // What each step records (RunOptions::record); a history row takes everything.
  RecordScope scope = options.record;
  if (sink || step_sink) scope = RecordScope{};
  const bool shears = scope.story_shears || scope.base_shears;
  const bool absolute = scope.accelerations || shears || scope.probes;
  // Element output peaks: every one, or the caller's subset (its values gathered from the
  // scratch by their positions there).
  std::vector<int> output_positions;
  PeakBands output_peaks([&] {
    std::vector<Peak*> peaks;
    if (scope.element_output_subset.empty()) {
      for (auto& element : res.element_outputs)
        for (Peak& peak : element) peaks.push_back(&peak);
      return peaks;
    }
    std::vector<std::pair<int, int>> subset = scope.element_output_subset;
    std::sort(subset.begin(), subset.end());
    subset.erase(std::unique(subset.begin(), subset.end()), subset.end());
    std::vector<int> first(res.element_outputs.size() + 1, 0);
    for (std::size_t e = 0; e < res.element_outputs.size(); ++e)
      first[e + 1] = first[e] + static_cast<int>(res.element_outputs[e].size());
    for (const auto& [e, k] : subset) {
      if (e < 0 || e >= static_cast<int>(res.element_outputs.size()) || k < 0 ||
          k >= static_cast<int>(res.element_outputs[e].size()))
        throw std::logic_error("run_analysis: no element output " + std::to_string(e) + "." +
                               std::to_string(k) + " to record");
      output_positions.push_back(first[e] + k);
      peaks.push_back(&res.element_outputs[e][k]);
    }
    return peaks;
  }());
  std::vector<double> subset_values(output_positions.size());

  // Storey and base shears of the committed state (work: the absolute accelerations).
  const auto record_shears = [&](double t) {
    mass_rows.multiply(work, inertia);
    for (std::size_t s = 0; s < above_story.size(); ++s) {
      double shear = 0.0;
      for (const int d : above_story[s]) shear -= inertia[d];
      story_shear_now[s] = shear;
      update_peak(res.story_shear[s], shear, t);
    }
    // Base shear: every force through the isolation layer and the isolated slab's supports,
    // isolator + isolation damping + the contacts at the base level (walls, a neighbour's base
    // slab); with the isolators on the ground, what reaches the foundation. The
    // superstructure's damping is internal to the levels and cancels in the sum; a base
    // contact's force on another structure is not on these levels.
    const Eigen::VectorXd& damping_force = stepper.c_v();  // C v
    for (std::size_t s = 0; s < above_base.size(); ++s) {
      if (above_base[s].empty()) continue;
      const StructureInfo& info = model.structures[s];
      if (!info.level_dofs_y.empty()) {
        // In plan: the equilibrium of the whole structure (its bearings may be springs in K).
        base_force.setZero();
        for (const int e : info.upper_contact_elements) model.elements[e]->add_force(base_force);
        double x = 0.0, y = 0.0;
        for (const int d : above_base[s]) x -= inertia[d] + base_force[d];
        for (const int d : above_base_y[s]) y -= inertia[d] + base_force[d];
        base_shear_now[s] = x;
        base_shear_y_now[s] = y;
        update_peak(res.base_shear[s], x, t);
        update_peak(res.base_shear_y[s], y, t);
        update_peak(res.base_shear_resultant[s], std::hypot(x, y), t);
        continue;
      }
      base_force.setZero();
      const int iso = model.structures[s].isolator_element;
      if (iso >= 0) model.elements[iso]->add_force(base_force);
      for (const int e : model.structures[s].base_contact_elements)
        model.elements[e]->add_force(base_force);
      double shear = 0.0;
      for (const int d : above_base[s]) shear += base_force[d] + damping_force[d];
      base_shear_now[s] = shear;
      update_peak(res.base_shear[s], shear, t);
    }
  };

  // Energy terms of the committed state, reached by a step h.
  const auto record_energy = [&](const GroundAcceleration& ag, double h) {
    const Eigen::VectorXd& u = stepper.u();
    const Eigen::VectorXd& v = stepper.v();
    double p_in = -v.dot(m_iota.col(0)) * ag.x;
    if (ag.y != 0.0) p_in -= v.dot(m_iota.col(1)) * ag.y;
    const double p_visc = v.dot(stepper.c_v());  // C v
    double p_elem = 0.0, stored = 0.0;
    stepper.batches().add_energy(v, p_elem, stored);
    e_in += 0.5 * h * (p_in_prev + p_in);
    e_visc += 0.5 * h * (p_visc_prev + p_visc);
    w_elem += 0.5 * h * (p_elem_prev + p_elem);
    p_in_prev = p_in;
    p_visc_prev = p_visc;
    p_elem_prev = p_elem;
    const double kinetic = 0.5 * v.dot(stepper.m_v());
    const double strain = 0.5 * u.dot(stepper.k_u());
    EnergyBalance& en = res.energy;
    en.input = e_in;
    en.kinetic = kinetic;
    en.elastic = strain + stored;
    en.viscous = e_visc;
    en.hysteretic = w_elem - stored;
    if (initial_energy < 0) {
      initial_energy = kinetic + strain + stored;
      stored_at_start = stored;
    }
    en.error = e_in + initial_energy - (kinetic + strain + e_visc + w_elem) - stored_at_start;
    max_in = std::max(max_in, std::abs(e_in) + initial_energy);
    max_err = std::max(max_err, std::abs(en.error));
  };

  auto record = [&](double t, const GroundAcceleration& ag, double h) {
    const Eigen::VectorXd& u = stepper.u();
    const Eigen::VectorXd& v = stepper.v();
    const Eigen::VectorXd& a = stepper.a();
    if (absolute)
      for (int i = 0; i < n; ++i) work[i] = a[i] + rigid(i, ag);  // absolute acceleration
    displacement_peaks.record(u.data(), t);
    if (scope.velocities) velocity_peaks.record(v.data(), t);
    if (scope.accelerations) acceleration_peaks.record(work.data(), t);
    for (std::size_t s = 0; s < res.stories.size(); ++s) {
      const Story& st = res.stories[s];
      const double drift = u[st.upper] - (st.lower >= 0 ? u[st.lower] : 0.0);
      // The ratio's peaks are the drift's divided by the height (x / h rounds monotonically in x
      // for a finite h > 0): a drift inside its peaks' band leaves the ratio's alone, undivided.
      const Peak& peak = res.drift[s];
      if (drift <= peak.positive && drift >= peak.negative && st.height > 0 &&
          st.height < std::numeric_limits<double>::infinity())
        continue;
      update_peak(res.drift[s], drift, t);
      update_peak(res.drift_ratio[s], drift / st.height, t);
    }
    if (shears) record_shears(t);
    for (std::size_t k = 0; k < options.tracked.size(); ++k) {
      const TrackedCoordinate& c = options.tracked[k];
      const double x = (c.dof_a >= 0 ? c.c_a * u[c.dof_a] : 0.0) +
                       (c.dof_b >= 0 ? c.c_b * u[c.dof_b] : 0.0) +
                       (c.dof_c >= 0 ? c.c_c * u[c.dof_c] : 0.0);
      update_peak(res.tracked[k], x, t);
    }
    if (scope.probes) probe_recorder.record(u.data(), work.data(), t, res.probes);
    if (scope.element_outputs) {
      stepper.batches().outputs(output_scratch.data());
      if (output_positions.empty()) {
        output_peaks.record(output_scratch.data(), t);
      } else {
        for (std::size_t k = 0; k < output_positions.size(); ++k)
          subset_values[k] = output_scratch[output_positions[k]];
        output_peaks.record(subset_values.data(), t);
      }
    }
    if (scope.energy) record_energy(ag, h);

    if (sink || step_sink) {
      double* r = row.data();
      *r++ = t;
      *r++ = ag.x;
      if (two_components) *r++ = ag.y;
      for (int i = 0; i < n; ++i) *r++ = u[i];
      for (int i = 0; i < n; ++i) *r++ = v[i];
      for (int i = 0; i < n; ++i) *r++ = a[i] + rigid(i, ag);
      r = std::copy(output_scratch.begin(), output_scratch.end(), r);
      for (std::size_t s = 0; s < above_base.size(); ++s) {
        if (above_base[s].empty()) continue;
        *r++ = base_shear_now[s];
        if (!model.structures[s].level_dofs_y.empty()) *r++ = base_shear_y_now[s];
      }
      std::copy(story_shear_now.begin(), story_shear_now.end(), r);
      if (step_sink) step_sink->row(row.data(), row.size());
    }
    if (sink) {
      // Every grid time up to this step's end: the step's own state on the grid, else sampled
      // inside the step (t_k > previous_t: earlier grid times were written by earlier steps).
      for (double t_k = static_cast<double>(next_row) * out_interval; t_k <= t + grid_tolerance;
           t_k = static_cast<double>(++next_row) * out_interval) {
        if (std::abs(t - t_k) <= grid_tolerance) {
          row[0] = t_k;
          sink->row(row.data(), row.size());
          continue;
        }
        history_row_between(previous_row, row, held_column, first_u_column, n, t_k, sampled_row);
        sink->row(sampled_row.data(), sampled_row.size());
      }
      row[0] = t;
      std::swap(row, previous_row);
    }
    // Every 64 steps: a struck-column step can take a millisecond, and the line must show.
    if (options.progress && (++progress_tick & 63) == 0) options.progress(t, total);
  };

  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  const auto initial = [&](const Eigen::VectorXd& x, const char* what) -> const Eigen::VectorXd& {
    if (x.size() == 0) return zero;
    if (x.size() != n)
      throw std::invalid_argument(std::string("initial ") + what + " has " +
                                  std::to_string(x.size()) + " entries for " + std::to_string(n) +
                                  " DOFs");
    return x;
  };
  stepper.start(initial(options.initial_displacement, "displacement"),
                initial(options.initial_velocity, "velocity"), ground(0, 0.0));
  record(0.0, ground(0, 0.0), 0.0);

  // Pseudocode of the stepping inside analysis interval i (position pos in [0, 1]):
  //   h = H / 2^level, clipped to the interval end; try the step
  //   not converged or local error > 1  -> halve (level + 1) and retry
  //   an element reports an event at fraction theta of the step -> retry with theta h
  //     (uncached K_hat), so that contact onset/separation falls on a step end
  //   accept; refine while h exceeds an element's step limit; coarsen when the error is small
  RunStatistics& st = res.stats;
  st.min_step = H;
  int level = 0;
  int settles_here = 0;
  const double min_fraction = std::ldexp(1.0, -max_level);
  // 2^-l for the levels 0..max_level (exact), looked up: ldexp twice a step was 2 % of a 2D run.
  std::vector<double> fraction_of_level(static_cast<std::size_t>(std::max(max_level, 0)) + 1);
  for (std::size_t l = 0; l < fraction_of_level.size(); ++l)
    fraction_of_level[l] = std::ldexp(1.0, -static_cast<int>(l));
  const auto level_fraction = [&](int l) {
    return l >= 0 && l <= max_level ? fraction_of_level[static_cast<std::size_t>(l)]
                                    : std::ldexp(1.0, -l);
  };
  const auto level_step = [&](int l) { return H * level_fraction(l); };
  // The elements with events or step limits (Element::has_events); the others are never asked.
  std::vector<int> eventful;
  for (int k = 0; k < n_elements; ++k)
    if (model.elements[k]->has_events()) eventful.push_back(k);
  // Raises the level until the step respects every element's limit (in fixed stepping too);
  // returns the limit.
  const auto refine_to_limit = [&]() {
    double limit = 1e300;
    for (const int k : eventful) limit = std::min(limit, model.elements[k]->step_limit());
    while (level < max_level && level_step(level) > limit) ++level;
    return limit;
  };
  std::vector<double> event_theta(model.elements.size(), 1.0);  // 1 for the eventless
  std::vector<char> settling(model.elements.size(), 0);
  // The settling elements switch status at the committed state; if a force jumped, the stepper
  // restarts from equilibrium (ground acceleration ag) and so does the power integrand.
  const auto settle_events = [&](const GroundAcceleration& ag) {
    bool jumped = false;
    for (std::size_t k = 0; k < model.elements.size(); ++k)
      if (settling[k]) jumped = model.elements[k]->settle_event() || jumped;
    std::fill(settling.begin(), settling.end(), 0);
    if (!jumped) return;
    stepper.restart(ag);
    ++st.restarts;
    p_elem_prev = 0.0;
    for (const auto& el : model.elements) p_elem_prev += el->power(stepper.v());
  };
  bool holding = false;  // the step being tried holds the elements' branches
  for (long i = 0; i < intervals; ++i) {
    double pos = 0.0;
    double forced = 0.0;  // > 0: the fraction of H of a step cut at an event
    while (pos < 1.0) {
      double frac = forced > 0 ? forced : level_fraction(level);
      bool regular = forced == 0.0;
      if (pos + frac > 1.0 - 1e-12 * frac) {
        regular = regular && pos + frac == 1.0;
        frac = 1.0 - pos;
      }
      const double h = frac * H;
      const GroundAcceleration ag1 = ground(i, pos + frac);
      const bool at_event = forced > 0;
      if (holding) {  // the held step is over (accepted or not): branches switch freely again
        for (const int k : eventful) model.elements[k]->hold_branch(false);
        holding = false;
      }
      StepOutcome out = stepper.try_step(h, ag1, regular, at_event);
      st.newton_iterations += out.iterations;
      if (!out.converged && frac <= min_fraction * (1 + 1e-9)) {
        // Newton fails at the smallest step: a force that jumps with the placement can make it
        // flip between the two sides for ever. Retry with every law on its committed branch.
        stepper.reject();
        for (const int k : eventful) model.elements[k]->hold_branch(true);
        holding = true;
        out = stepper.try_step(h, ag1, regular, at_event);
        st.newton_iterations += out.iterations;
        if (out.converged) ++st.held_steps;
      }
      const double err = adaptive && out.converged ? stepper.error_norm(force_scale) : 0.0;
      if (!out.converged || err > 1.0) {
        // Error-based halving only when adaptive; a Newton failure (e.g. a contact switching
        // inside the step) is retried with half the step in fixed stepping too.
        const bool can_halve = frac > min_fraction * (1 + 1e-9);
        if (can_halve && (adaptive || !out.converged)) {
          stepper.reject();
          if (forced > 0) {
            // A step cut to end at an event failed: half of it no longer ends at the event, so
            // the event is dropped (no element may settle at the wrong instant) and found
            // again by regular, unfrozen steps of at most half the cut step.
            while (level < max_level && level_fraction(level) > 0.5 * forced) ++level;
            forced = 0.0;
            std::fill(settling.begin(), settling.end(), 0);
          } else {
            ++level;
          }
          level = std::min(level, max_level);
          ++st.rejected_steps;
          continue;
        }
        if (!out.converged) {
          int dof = 0;
          const double t = (static_cast<double>(i) + pos) * H;
          const std::string msg = divergence_message(model, stepper, t, h, out.iterations, dof);
          throw AnalysisError(t, model.dofs[dof].label, msg);
        }
      }
      if (cfg.locate_events && !at_event) {
        // Status changes of contacts (onset, separation) are made to fall on a step boundary,
        // where the element switches and the stepper restarts from equilibrium:
        //   event at the start (theta ~ 0): switch now, redo the step;
        //   inside: redo the step cut to end there (status frozen), then switch;
        //   at the end (theta ~ 1): redo the same step with the status frozen, then switch.
        double theta = 1.0;
        for (const int k : eventful) {
          event_theta[k] = model.elements[k]->event_fraction();
          theta = std::min(theta, event_theta[k]);
        }
        if (theta < 1.0) {
          stepper.reject();
          ++st.rejected_steps;
          const double tol = 1e-4;
          for (std::size_t k = 0; k < model.elements.size(); ++k)
            settling[k] =
                event_theta[k] <= std::max(theta * (1.0 + 1e-12), theta < tol ? tol : 0.0);
          if (theta < tol) {
            settle_events(ground(i, pos));
            refine_to_limit();  // a contact that just started wants its own step from the start
            if (++settles_here > 4)
              throw AnalysisError((static_cast<double>(i) + pos) * H, "",
                                  "event loop: contact status does not settle");
            continue;
          }
          forced = std::min(theta, 1.0) * frac;
          continue;
        }
      }
      settles_here = 0;
      stepper.accept();
      forced = 0.0;
      pos = pos + frac >= 1.0 - 1e-12 ? 1.0 : pos + frac;
      ++st.steps;
      st.min_step = std::min(st.min_step, h);
      st.max_step = std::max(st.max_step, h);
      const double t = (static_cast<double>(i) + pos) * H;
      if (stepper.u().cwiseAbs().maxCoeff() > 1e3) {
        int dof = 0;
        stepper.u().cwiseAbs().maxCoeff(&dof);
        throw AnalysisError(t, model.dofs[dof].label,
                            "analysis diverged at t = " + std::to_string(t) + " s, DOF '" +
                                model.dofs[dof].label +
                                "': displacement exceeds 1000 m. Hint: check the units of "
                                "stiffnesses and masses, and the record's unit and scale.");
      }
      record(t, ag1, h);                 // the step just taken, with the forces before any switch
      if (at_event) settle_events(ag1);  // the step ended at an event: switch status there
      if (options.observer) options.observer->after_step(t, model);
      if (adaptive) {
        const double limit = refine_to_limit();  // also gives a new contact its own step
        if (level > 0 && err < 0.1 && level_step(level - 1) <= limit) --level;
      } else {
        // Fixed stepping: back to the fixed step after a Newton-failure halving, but never
        // longer than an element's limit (a contact's step, the time of impact).
        level = 0;
        refine_to_limit();
      }
    }
  }

  if (holding)
    for (const int k : eventful) model.elements[k]->hold_branch(false);
  EnergyBalance& en = res.energy;
  const double supplied = std::abs(en.input) + std::max(initial_energy, 0.0);
  en.relative_error = supplied > 0 ? std::abs(en.error) / supplied : 0.0;
  en.max_relative_error = max_in > 0 ? max_err / max_in : 0.0;
  st.duration = static_cast<double>(intervals) * H;
  st.interval = H;
  res.final_displacement.assign(stepper.u().data(), stepper.u().data() + n);
  st.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return res;
}

}  // namespace isopound
