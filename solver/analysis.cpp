// Time-history analysis driver: walks the record interval by interval; inside an interval the
// step is halved where the local error estimate says so (steps stay aligned with the samples).
#include "solver/analysis.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "solver/isolator.h"
#include "solver/modes.h"
#include "solver/newmark.h"

namespace isopound {

std::vector<Story> stories_of(const Model& model) {
  std::vector<Story> stories;
  for (const StructureInfo& s : model.structures) {
    const std::size_t first_floor = s.has_base ? 1 : 0;
    for (std::size_t k = first_floor; k < s.level_dofs.size(); ++k) {
      Story story;
      const std::size_t number = k - first_floor + 1;
      story.label = s.name + "/story " + std::to_string(number);
      story.upper = s.level_dofs[k];
      story.lower = k == 0 ? -1 : s.level_dofs[k - 1];
      story.height = s.story_heights[number - 1];
      stories.push_back(story);
    }
  }
  return stories;
}

namespace {

void update(Peak& peak, double value, double t) {
  const double a = std::abs(value);
  if (a > peak.value) {
    peak.value = a;
    peak.time = t;
  }
}

// Ground acceleration on the refined grid: interval i, position pos out of `units`.
struct GroundSampler {
  const GroundMotion& motion;
  int per_sample;  // analysis intervals per record interval
  long units;      // finest positions per analysis interval

  double operator()(long interval, long pos) const {
    long k = interval / per_sample;
    long j = interval % per_sample;
    double frac = (static_cast<double>(j) + static_cast<double>(pos) / units) / per_sample;
    if (frac >= 1.0) {
      ++k;
      frac = 0.0;
    }
    const auto& a = motion.acceleration;
    const long n = static_cast<long>(a.size());
    const double a0 = k < n ? a[k] : 0.0;
    const double a1 = k + 1 < n ? a[k + 1] : 0.0;
    return a0 + frac * (a1 - a0);
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

}  // namespace

double shortest_period(Model& model) {
  const int n = model.size();
  Eigen::MatrixXd k = model.stiffness;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  for (auto& e : model.elements) {
    e->set_trial(zero, zero);
    e->add_tangent(k, 0.0);
    e->revert();
  }
  try {
    return compute_modes(k, model.mass, model.influence).period.minCoeff();
  } catch (const std::invalid_argument&) {
    return 0.0;  // a mechanism at rest (e.g. only contacts hold a DOF): no period rule
  }
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
  res.element_outputs.resize(n_elements);
  for (int e = 0; e < n_elements; ++e) res.element_outputs[e].resize(model.elements[e]->output_count());

  NewmarkStepper stepper(model, {cfg.newton_tolerance, cfg.max_iterations});

  // Analysis interval H divides the record interval so that H <= the largest step.
  const bool adaptive = cfg.stepping == AnalysisConfig::Stepping::kAdaptive;
  double max_step = cfg.dt;
  if (adaptive && max_step <= 0 && cfg.steps_per_period > 0)
    max_step = shortest_period(model) / cfg.steps_per_period;
  int per_sample = 1;
  if (max_step > 0)
    per_sample = std::max(1, static_cast<int>(std::ceil(motion.dt / max_step - 1e-9)));
  const double H = motion.dt / per_sample;
  const double total = motion.duration() + options.extra_time;
  const long intervals = static_cast<long>(std::ceil(total / H - 1e-9));
  const int max_level = adaptive ? cfg.max_halvings : 0;
  const long units = 1L << max_level;
  const GroundSampler ground{motion, per_sample, units};

  // Error scale per DOF: the weight of the DOF's mass times the tolerance (see newmark.h).
  Eigen::VectorXd force_scale(n);
  for (int i = 0; i < n; ++i)
    force_scale[i] = cfg.tolerance * kGravity * std::max(model.mass(i, i), 1e-12);

  // History layout.
  const double out_interval = options.output.interval > 0 ? options.output.interval : motion.dt;
  if (options.output.histories) {
    auto& c = res.history.columns;
    c = {"time [s]", "ground_acceleration [m/s2]"};
    for (const Dof& d : model.dofs) c.push_back(d.label + " u [m]");
    for (const Dof& d : model.dofs) c.push_back(d.label + " v [m/s]");
    for (const Dof& d : model.dofs) c.push_back(d.label + " a_abs [m/s2]");
    for (const auto& e : model.elements)
      for (int k = 0; k < e->output_count(); ++k)
        c.push_back(e->label() + " " + e->output_name(k) + " [" + e->output_unit(k) + "]");
    res.history.values.reserve(c.size() * static_cast<std::size_t>(total / out_interval + 2));
  }
  double next_output = 0.0;

  // Energy terms (trapezoidal rule on the powers).
  Eigen::VectorXd work(n);
  const Eigen::VectorXd m_iota = model.mass * model.influence;
  double p_in_prev = 0.0, p_visc_prev = 0.0, p_elem_prev = 0.0;
  double e_in = 0.0, e_visc = 0.0, w_elem = 0.0, max_in = 0.0, max_err = 0.0;

  auto record = [&](double t, double ag, double h) {
    const Eigen::VectorXd& u = stepper.u();
    const Eigen::VectorXd& v = stepper.v();
    const Eigen::VectorXd& a = stepper.a();
    for (int i = 0; i < n; ++i) {
      update(res.displacement[i], u[i], t);
      update(res.velocity[i], v[i], t);
      update(res.absolute_acceleration[i], a[i] + model.influence[i] * ag, t);
    }
    for (std::size_t s = 0; s < res.stories.size(); ++s) {
      const Story& st = res.stories[s];
      const double drift = u[st.upper] - (st.lower >= 0 ? u[st.lower] : 0.0);
      update(res.drift[s], drift, t);
      update(res.drift_ratio[s], drift / st.height, t);
    }
    for (int e = 0; e < n_elements; ++e)
      for (int k = 0; k < model.elements[e]->output_count(); ++k)
        update(res.element_outputs[e][k], model.elements[e]->output(k), t);

    // Energy.
    const double p_in = -v.dot(m_iota) * ag;
    work.noalias() = model.damping * v;
    const double p_visc = v.dot(work);
    double p_elem = 0.0, stored = 0.0;
    for (const auto& el : model.elements) {
      p_elem += el->power(v);
      stored += el->stored_energy();
    }
    e_in += 0.5 * h * (p_in_prev + p_in);
    e_visc += 0.5 * h * (p_visc_prev + p_visc);
    w_elem += 0.5 * h * (p_elem_prev + p_elem);
    p_in_prev = p_in;
    p_visc_prev = p_visc;
    p_elem_prev = p_elem;
    work.noalias() = model.mass * v;
    const double kinetic = 0.5 * v.dot(work);
    work.noalias() = model.stiffness * u;
    const double strain = 0.5 * u.dot(work);
    EnergyBalance& en = res.energy;
    en.input = e_in;
    en.kinetic = kinetic;
    en.elastic = strain + stored;
    en.viscous = e_visc;
    en.hysteretic = w_elem - stored;
    en.error = e_in - (kinetic + strain + e_visc + w_elem);
    max_in = std::max(max_in, std::abs(e_in));
    max_err = std::max(max_err, std::abs(en.error));

    if (options.output.histories && t >= next_output - 1e-9 * out_interval) {
      auto& vals = res.history.values;
      vals.push_back(t);
      vals.push_back(ag);
      for (int i = 0; i < n; ++i) vals.push_back(u[i]);
      for (int i = 0; i < n; ++i) vals.push_back(v[i]);
      for (int i = 0; i < n; ++i) vals.push_back(a[i] + model.influence[i] * ag);
      for (const auto& el : model.elements)
        for (int k = 0; k < el->output_count(); ++k) vals.push_back(el->output(k));
      next_output += out_interval;
      while (next_output <= t + 1e-9 * out_interval) next_output += out_interval;
    }
  };

  stepper.start(ground(0, 0));
  record(0.0, ground(0, 0), 0.0);

  RunStatistics& st = res.stats;
  st.min_step = H;
  int level = 0;
  for (long i = 0; i < intervals; ++i) {
    long pos = 0;
    while (pos < units) {
      const long step_units = units >> level;
      const double h = H / static_cast<double>(1L << level);
      const double ag1 = ground(i, pos + step_units);
      const StepOutcome out = stepper.try_step(h, ag1);
      st.newton_iterations += out.iterations;
      const double err = adaptive && out.converged ? stepper.error_norm(force_scale) : 0.0;
      if (!out.converged || err > 1.0) {
        if (level < max_level) {
          stepper.reject();
          ++level;
          ++st.rejected_steps;
          continue;
        }
        if (!out.converged) {
          int dof = 0;
          const double t = (static_cast<double>(i) + static_cast<double>(pos) / units) * H;
          const std::string msg = divergence_message(model, stepper, t, h, out.iterations, dof);
          throw AnalysisError(t, model.dofs[dof].label, msg);
        }
      }
      stepper.accept();
      pos += step_units;
      ++st.steps;
      st.min_step = std::min(st.min_step, h);
      st.max_step = std::max(st.max_step, h);
      const double t = (static_cast<double>(i) + static_cast<double>(pos) / units) * H;
      if (stepper.u().cwiseAbs().maxCoeff() > 1e3) {
        int dof = 0;
        stepper.u().cwiseAbs().maxCoeff(&dof);
        throw AnalysisError(t, model.dofs[dof].label,
                            "analysis diverged at t = " + std::to_string(t) + " s, DOF '" +
                                model.dofs[dof].label +
                                "': displacement exceeds 1000 m. Hint: check the units of "
                                "stiffnesses and masses, and the record's unit and scale.");
      }
      record(t, ag1, h);
      if (adaptive && level > 0 && err < 0.1 && pos % (2 * step_units) == 0) --level;
    }
  }

  EnergyBalance& en = res.energy;
  en.relative_error = en.input != 0 ? std::abs(en.error) / std::abs(en.input) : 0.0;
  en.max_relative_error = max_in > 0 ? max_err / max_in : 0.0;
  st.duration = static_cast<double>(intervals) * H;
  st.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return res;
}

}  // namespace isopound
