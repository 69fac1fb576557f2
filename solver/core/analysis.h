// One nonlinear time-history analysis of a Model under a ground motion: adaptive Newmark
// stepping aligned with the record samples, peaks, energy balance and histories.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "solver/core/analysis_config.h"
#include "solver/core/model.h"
#include "solver/core/peak.h"
#include "solver/core/probe_record.h"
#include "solver/excitation/ground_motion.h"

namespace isopound {

// A diverging analysis: where and when it stopped, and a hint.
class AnalysisError : public std::runtime_error {
 public:
  AnalysisError(double time, std::string dof, const std::string& what)
      : std::runtime_error(what), time_(time), dof_(std::move(dof)) {}
  double time() const { return time_; }
  const std::string& dof() const { return dof_; }

 private:
  double time_;
  std::string dof_;
};

// A story: deformation u[upper] - u[lower] (lower = -1: the ground).
struct Story {
  std::string label;
  int lower = -1;
  int upper = 0;
  double height = 0.0;
};

struct EnergyBalance {
  // Each term integrated with the trapezoidal rule in time from its power (see THEORY-notes).
  double input = 0.0;               // -int v^T M iota a_g dt
  double kinetic = 0.0;             // v^T M v / 2
  double elastic = 0.0;             // u^T K u / 2 + recoverable energy of the elements
  double viscous = 0.0;             // int v^T C v dt
  double hysteretic = 0.0;          // element work minus their recoverable energy
  double error = 0.0;               // input - (kinetic + elastic + viscous + hysteretic) at the end
  double relative_error = 0.0;      // |error| / input at the end
  double max_relative_error = 0.0;  // max_t |error(t)| / max_t input(t)
};

struct RunStatistics {
  long steps = 0;           // accepted steps
  long rejected_steps = 0;  // steps redone with half the size
  long newton_iterations = 0;
  long restarts = 0;    // restarts from equilibrium after a force jump at an event
  long held_steps = 0;  // smallest steps taken with a law's branch held (Element::hold_branch)
  double min_step = 0.0, max_step = 0.0;  // s
  double wall_seconds = 0.0;
  double duration = 0.0;     // s of analysed time
  double record_end = 0.0;   // s, the record's duration + extra_time (the natural end)
  double t_end = 0.0;        // s, AnalysisConfig::t_end as asked (0: none); may pass record_end
  double interval = 0.0;     // s, the analysis interval H (the record interval / an integer)
  double step_period = 0.0;  // s, T_min of the largest-step rule (0: not used or a mechanism)
};

struct History {
  std::vector<std::string> columns;  // "time", ..., with units in brackets
  std::vector<double> values;        // row-major, columns.size() per row
  std::size_t rows() const { return columns.empty() ? 0 : values.size() / columns.size(); }
};

// Where history rows go as the analysis produces them: a file (report.h) streams them, so memory
// does not grow with the record; without a sink they are kept in AnalysisResult::history.
class HistorySink {
 public:
  virtual ~HistorySink() = default;
  virtual void begin(const std::vector<std::string>& columns) = 0;
  virtual void row(const double* values, std::size_t count) = 0;  // count = columns.size()
};

// A coordinate c_a u_a + c_b u_b tracked over time (dof -1: the ground, contributes nothing),
// e.g. how far the two sides of a contact would close without the contact.
struct TrackedCoordinate {
  int dof_a = -1;
  double c_a = 0.0;
  int dof_b = -1;
  double c_b = 0.0;
  int dof_c = -1;  // a third term, e.g. the rotation of a point of a rigid floor
  double c_c = 0.0;
};

// Sees the model after every accepted step (e.g. a contact-event log). Called with the model's
// elements in their committed state; must not change them.
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  virtual void after_step(double t, const Model& model) = 0;
};

struct AnalysisResult {
  std::vector<Story> stories;
  std::vector<Peak> displacement;           // per DOF, relative to the ground, m
  std::vector<Peak> velocity;               // per DOF, relative, m/s
  std::vector<Peak> absolute_acceleration;  // per DOF, m/s^2
  std::vector<Peak> drift;                  // per story, m
  std::vector<Peak> drift_ratio;            // per story
  // Storey shear, N: the force the storey transmits, V = -sum over the levels above it of
  // (M a_abs); positive when it pushes the part above in +x.
  std::vector<Peak> story_shear;  // per story
  // Base shear of each structure with an isolated base, N: every force reaching the foundation
  // from the structure, isolator + isolation damping + the contacts at the base level
  // (StructureInfo::base_contact_elements), positive when it resists a +x displacement (pulls
  // in -x); without contacts above the base level it equals -sum over the levels of M a_abs.
  // Per structure (0 if fixed base). A structure in plan (StructureInfo::level_dofs_y): the
  // x component, -sum over its levels of (M a_abs)_x minus its contacts above the base; its y
  // component and the resultant sqrt(x^2 + y^2) at each instant in the next two (0 in 2D).
  std::vector<Peak> base_shear;
  std::vector<Peak> base_shear_y;
  std::vector<Peak> base_shear_resultant;
  std::vector<double> final_displacement;          // per DOF at the end of the analysis, m
  std::vector<std::vector<Peak>> element_outputs;  // per element, per output
  std::vector<Peak> tracked;                       // per RunOptions::tracked
  std::vector<ProbePeaks> probes;                  // per Model::probes entry
  EnergyBalance energy;
  RunStatistics stats;
  History history;
};

// What run_analysis records each step beside the displacement, drift and tracked peaks and the
// final displacement (always kept). A caller that reads only some results (a study's outputs)
// switches the others off: their fields of AnalysisResult then stay at zero. Histories
// (output.histories, a history or step sink) take every column, whatever is switched off here.
struct RecordScope {
  bool velocities = true;       // AnalysisResult::velocity
  bool accelerations = true;    // absolute_acceleration
  bool story_shears = true;     // story_shear
  bool base_shears = true;      // base_shear, base_shear_y, base_shear_resultant
  bool element_outputs = true;  // element_outputs
  bool probes = true;           // probes
  bool energy = true;           // energy
  // With element_outputs: the (element, output) peaks to record; empty: every one. The others
  // stay at zero.
  std::vector<std::pair<int, int>> element_output_subset;
};

struct RunOptions {
  AnalysisConfig analysis;
  OutputConfig output;
  double extra_time = 0.0;  // s of free vibration after the record
  // Initial displacements and velocities (relative to the ground); empty = at rest.
  Eigen::VectorXd initial_displacement;
  Eigen::VectorXd initial_velocity;
  std::vector<TrackedCoordinate> tracked;  // peaks in AnalysisResult::tracked
  // Histories go here when set (and output.histories); else into AnalysisResult::history.
  HistorySink* history_sink = nullptr;
  // Every accepted step's row (the columns of the histories), at the step's own time: what exact
  // floor spectra need (output.floor_spectra, solver/io/step_accelerations.h).
  HistorySink* step_sink = nullptr;
  StepObserver* observer = nullptr;  // after every accepted step, when set
  RecordScope record;                // everything by default (summary.json reads everything)
  // Called now and then (every 4096 accepted steps) with the analysed and the total time, s.
  std::function<void(double t, double total)> progress;
};

// Stories of every structure in the model, in order.
std::vector<Story> stories_of(const Model& model);

// The model's stiffness linearised at rest: K plus every element's tangent at u = v = 0 (each
// element's trial state is reverted after), but for element `excluded` (an index into
// model.elements; -1: none), e.g. an isolator whose stiffness the caller chooses itself.
Eigen::MatrixXd stiffness_at_rest(Model& model, int excluded = -1);

// Shortest undamped period of the model linearised at rest (element tangents at zero), s;
// 0 if the model is a mechanism at rest.
double shortest_period(Model& model);

// The period that sets the largest adaptive step (T_min of AnalysisConfig::dt): the shortest
// period of the model linearised at rest among the modes `rule` counts; with kParticipating,
// only modes whose effective modal mass ratio along x or along y (each column of the influence
// matrix that moves any mass) is >= threshold. 0 if the model is a mechanism at rest.
double max_step_period(Model& model, AnalysisConfig::MaxStepRule rule, double threshold);

// Runs the analysis (from rest unless initial conditions are given). Throws AnalysisError if it
// diverges.
AnalysisResult run_analysis(Model& model, const GroundMotion& motion, const RunOptions& options);

}  // namespace isopound
