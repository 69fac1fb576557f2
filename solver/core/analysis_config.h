// What the stepper (solver/core/analysis.h) needs to know of an analysis: time stepping,
// tolerances and history output. Plain structs, SI; read from YAML in solver/io/model_input.cpp.
#pragma once

namespace isopound {

struct AnalysisConfig {
  enum class Stepping { kAdaptive, kFixed };
  Stepping stepping = Stepping::kAdaptive;
  // Fixed: the step. Adaptive: the largest step; 0 = min(record interval,
  // T_min / steps_per_period) with T_min the shortest period of the initial linearised model
  // among the modes max_step_rule counts. Steps always divide the record interval, so samples
  // are never skipped.
  double dt = 0.0;
  double steps_per_period = 25.0;
  // Which modes set T_min: every mode, or only those whose effective modal mass ratio along x
  // or y, Gamma^2 / (iota^T M iota), is at least participation_threshold (THEORY-notes.md,
  // "Largest step"). The model input defaults to kParticipating for 3D structures and keeps
  // kAllModes for 2D buildings (their steps and results unchanged).
  enum class MaxStepRule { kAllModes, kParticipating };
  MaxStepRule max_step_rule = MaxStepRule::kAllModes;
  double participation_threshold = 1e-5;
  // Adaptive: local error tolerance (see THEORY-notes.md, "Time integration").
  double tolerance = 1e-4;  // 1e-3 until issue 8: see bench/RESULTS.md, "Convergence battery"
  int max_halvings = 16;    // smallest adaptive step = dt / 2^max_halvings
  // During a contact the step is at most (contact period) / steps_per_contact, with the
  // contact period pi sqrt(m_eff / k_tangent); before a contact, at most the time of impact.
  // Both in fixed stepping too (the fixed dt is then an upper bound).
  double steps_per_contact = 100.0;
  bool locate_events = true;  // cut steps at contact onset / separation / phase change
  // Stop the analysis at this time, s (0: at the record's end plus extra_time). For comparing
  // runs over a window (e.g. up to shortly after the first impacts, THEORY §12).
  double t_end = 0.0;
  double newton_tolerance = 1e-9;  // relative residual, see newmark.h
  int max_iterations = 25;
  // Newton's linear solve eliminates the DOFs no element touches (newmark.h); false: the whole
  // matrix every iteration. Not an input key: the results agree to round-off (tests compare).
  bool block_elimination = true;
};

struct OutputConfig {
  double interval = 0.0;  // s between rows of histories.csv; 0 = every record sample
  bool histories = true;
  // Every accepted step's absolute accelerations (and the ground's) to step-accelerations.csv,
  // from which isopound-post floor-spectra computes exact floor spectra (docs/floor-spectra.md).
  bool floor_spectra = false;
};

}  // namespace isopound
