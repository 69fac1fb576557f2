// summary.json section and console lines of 3D buildings: per floor the centre of mass and the
// corners, per storey every column's drift (x, y, resultant at each instant), their envelope.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "solver/structures/config3d.h"
#include "solver/structures/job.h"

namespace isopound {

// "buildings_3d": per building, levels (u, v, theta at the DOFs; centre of mass and corners:
// displacement and absolute acceleration x, y, resultant), storeys (each column's drift x, y,
// resultant and ratio; the envelope over columns; the corner columns), bearings (peaks).
nlohmann::json summary3d_json(const JobResult& job);
// The grid's corner columns among a storey's column labels "A1".."D4": the extreme letters and
// numbers (A1, D1, A4, D4); empty when a label is not a grid label (letter + number).
std::vector<std::string> corner_column_labels(const std::vector<std::string>& labels);
// "contacts_3d": per polygon contact pair, impacts, first-impact time, peaks of F_N, F_T, area,
// δ_N and impact velocity, time in stick and slip, friction- and impact-dissipated energy, and
// passivity: completed episodes, the largest net work of the contact forces over one episode.
nlohmann::json contacts3d_json(const JobResult& job);
// "unobstructed_3d" (--compare-unobstructed): per building and level the peaks without
// contacts and the amplification of each; the critical gap of each moat wall.
nlohmann::json unobstructed3d_json(const JobResult& job, const UnobstructedResult& free_run);
void print_unobstructed3d(std::ostream& out, const JobResult& job,
                          const UnobstructedResult& free_run);
// The console summary of 3D buildings (after the ground-motion line).
void print_summary3d(std::ostream& out, const JobResult& job);
// `isopound modes` for 3D buildings: fixed-base and isolated (bearings at K_post and at K_el)
// periods with the effective mass in x and y and the torsional share of each mode.
void print_modes3d(std::ostream& out, const ModelConfig& config);

}  // namespace isopound
