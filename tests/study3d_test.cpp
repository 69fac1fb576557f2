// Studies of 3D models: peak selectors at plan points, columns and contacts checked against the
// run summary (an independent path through the same run), incidence-angle ranges in degrees,
// record pairs, point-valued axes, and the same table for -j 1 and -j 2 over an angle sweep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "solver/elements/polygon_contact.h"
#include "solver/io/model_input.h"
#include "solver/io/report3d.h"
#include "solver/io/units.h"
#include "solver/structures/config3d.h"
#include "solver/structures/contact_log.h"
#include "solver/structures/job.h"
#include "solver/study/study_cases.h"
#include "solver/study/study_outputs.h"
#include "solver/study/study_runner.h"
#include "solver/study/study_spec.h"
#include "solver/study/study_store.h"
#include "tests/study_test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A scratch directory removed when the test process exits.
struct ScratchDir {
  fs::path path = test::study_scratch("study3d");
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

const fs::path& scratch() {
  static const ScratchDir dir;
  return dir.path;
}

Study load_study_text(const std::string& name, const std::string& text) {
  const fs::path path = scratch() / name;
  test::write_file(path, text);
  return load_study_file(path.string());
}

std::string config(const char* name) {
  return (test::source_dir() / "configs" / name).string();
}

// A short two-component pulse (L and half of it as T): a 3D run of a few hundred steps.
const char* kPulsePair =
    "ground_motion: {L: {pulse: {amplitude: 0.8 m/s, period: 2 s, duration: 4 s, dt: 0.01 s}}, "
    "T: {pulse: {amplitude: 0.4 m/s, period: 2 s, duration: 4 s, dt: 0.01 s}}, angle: 30 deg}";

// The eccentric thesis building (e_x = e_y = 0.6 m) under the pulse pair, run once.
const JobResult& eccentric_run() {
  static const JobResult job = [] {
    const fs::path path = scratch() / "eccentric.yaml";
    std::string text = test::read_file(config("3d-eccentric-v30.yaml"));
    text = text.substr(0, text.find("ground_motion:")) + kPulsePair + "\n";
    test::write_file(path, text);
    return run_job(load_model_file(path.string()));
  }();
  return job;
}

double peak(const std::string& selector, const JobResult& job) {
  return evaluate_output(resolve_output(parse_output_selector(selector), job.model), job.analysis,
                         job.motion_peaks);
}

double value(const json& peak_json) {
  return peak_json.at("value").get<double>();
}

// The largest value of `get` over the items of a JSON array.
template <class Get>
double max_over(const json& items, Get get) {
  double m = 0.0;
  for (const json& item : items) m = std::max(m, get(item));
  return m;
}

TEST(Study3DSelectors, PlanPointsDofsAndColumnsMatchTheRunSummary) {
  const JobResult& job = eccentric_run();
  const json b = summary3d_json(job).at(0);
  const json& levels = b.at("levels");  // base, floor 1, floor 2, floor 3
  const json& storeys = b.at("storeys");
  ASSERT_EQ(levels.size(), 4u);
  ASSERT_EQ(storeys.size(), 3u);
  const auto cm = [&](int l, const char* what, const char* c) {
    return value(levels[l].at("centre_of_mass").at(what).at(c));
  };
  const auto corners = [&](int l, const char* what) {
    return max_over(levels[l].at("corners"),
                    [&](const json& c) { return value(c.at(what).at("resultant")); });
  };
  // The same numbers reached two ways must be equal, not close.
  EXPECT_EQ(peak("base.displacement", job), cm(0, "displacement", "resultant"));
  EXPECT_EQ(peak("base.cm.displacement", job), cm(0, "displacement", "resultant"));
  EXPECT_EQ(peak("base.displacement_x", job), cm(0, "displacement", "x"));
  EXPECT_EQ(peak("floor2.cm.displacement_y", job), cm(2, "displacement", "y"));
  EXPECT_EQ(peak("roof.absolute_acceleration", job), cm(3, "absolute_acceleration", "resultant"));
  EXPECT_EQ(peak("floor1.absolute_acceleration_x", job), cm(1, "absolute_acceleration", "x"));
  EXPECT_EQ(peak("base.corners.displacement", job), corners(0, "displacement"));
  EXPECT_EQ(peak("base.corner3.displacement", job),
            value(levels[0].at("corners")[2].at("displacement").at("resultant")));
  EXPECT_EQ(
      peak("roof.points.absolute_acceleration", job),
      std::max(corners(3, "absolute_acceleration"), cm(3, "absolute_acceleration", "resultant")));
  EXPECT_EQ(peak("floors.corners.absolute_acceleration", job),
            std::max({corners(1, "absolute_acceleration"), corners(2, "absolute_acceleration"),
                      corners(3, "absolute_acceleration")}));
  EXPECT_EQ(peak("levels.corners.displacement", job),
            std::max({corners(0, "displacement"), corners(1, "displacement"),
                      corners(2, "displacement"), corners(3, "displacement")}));
  EXPECT_EQ(peak("floor2.v", job), value(levels[2].at("v")));
  EXPECT_EQ(peak("base.u", job), value(levels[0].at("u")));
  EXPECT_EQ(peak("floors.theta", job),
            max_over(json::array({levels[1], levels[2], levels[3]}),
                     [](const json& l) { return value(l.at("theta")); }));
  // Eccentric: the floors twist, and a corner moves more than the centre of mass.
  EXPECT_GT(peak("roof.theta", job), 1e-4);
  EXPECT_GT(peak("base.corners.displacement", job), peak("base.displacement", job));

  // Columns: the envelope over columns, the corner columns, one column by name.
  const auto envelope = [&](int s, const char* q) {
    return value(storeys[s].at("envelope_over_columns").at(q));
  };
  EXPECT_EQ(peak("story2.drift", job), envelope(1, "resultant"));
  EXPECT_EQ(peak("stories.drift_ratio", job),
            std::max({envelope(0, "drift_ratio"), envelope(1, "drift_ratio"),
                      envelope(2, "drift_ratio")}));
  double corner_ratio_1 = 0.0;
  for (const auto& [label, c] : storeys[0].at("corner_columns").items())
    corner_ratio_1 = std::max(corner_ratio_1, value(c.at("drift_ratio")));
  ASSERT_EQ(storeys[0].at("corner_columns").size(), 4u);  // A1, D1, A4, D4
  EXPECT_EQ(peak("story1.corners.drift_ratio", job), corner_ratio_1);
  double a1_x = -1.0;
  for (const json& c : storeys[2].at("columns"))
    if (c.at("label") == "A1") a1_x = value(c.at("x"));
  EXPECT_EQ(peak("story3.A1.drift_x", job), a1_x);
  // The grid's corner columns are the extreme ones here (rigid floors twisting): the envelope
  // over all columns equals the envelope over the corners.
  EXPECT_EQ(peak("stories.corners.drift_ratio", job), peak("stories.drift_ratio", job));
  EXPECT_LE(peak("story1.B2.drift_ratio", job), peak("story1.corners.drift_ratio", job));

  // Bearings, by element pattern.
  EXPECT_EQ(peak("bearing*.deformation", job),
            max_over(b.at("bearings"), [](const json& e) { return value(e.at("deformation")); }));
  EXPECT_EQ(peak("bearing A1.force", job), value(b.at("bearings")[0].at("force")));
}

TEST(Study3DSelectors, ResidualDisplacementIsTheResultantAtTheEndOfThePoint) {
  const JobResult& job = eccentric_run();
  // Independently: the base slab's centre of mass sits at e = (0.6 m, 0.6 m) from the plan
  // origin, where its DOFs are; a rigid slab moves it by (u - e_y theta, v + e_x theta).
  const int d = job.model.structures.front().level_dofs.front();
  const std::vector<double>& q = job.analysis.final_displacement;
  const double e = 0.6;
  const double expected = std::hypot(q[d] - e * q[d + 2], q[d + 1] + e * q[d + 2]);
  EXPECT_NEAR(peak("base.residual_displacement", job), expected,
              1e-15 * std::abs(expected) + 1e-18);
  EXPECT_GT(expected, 1e-3);  // the pulse leaves the base displaced: the check is not 0 = 0
}

TEST(Study3DSelectors, GrammarErrorsNameTheProblem) {
  const auto parse_error = [](const std::string& text) {
    try {
      parse_output_selector(text);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(parse_error("base.corner0.displacement").find("expected cm, corners, corner<K>"),
            std::string::npos);
  EXPECT_NE(parse_error("base.cm.theta").find("no plan point"), std::string::npos);
  EXPECT_NE(parse_error("roof.corners.velocity").find("not velocity"), std::string::npos);
  EXPECT_NE(parse_error("story1.corners.shear").find("not a column's"), std::string::npos);
  EXPECT_NE(parse_error("base.drift_x").find("drifts belong to stories"), std::string::npos);
  EXPECT_NE(parse_error("story1.rotation").find("drift_x"), std::string::npos);

  const auto resolve_error = [](const std::string& text, const Model& model) {
    const OutputSelector selector = parse_output_selector(text);
    try {
      resolve_output(selector, model);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const Model& m3 = eccentric_run().model;
  EXPECT_NE(resolve_error("base.velocity", m3).find("the building is 3D"), std::string::npos);
  EXPECT_NE(resolve_error("story1.shear", m3).find("with p_delta: true"), std::string::npos);
  EXPECT_NE(resolve_error("story1.Z9.drift", m3).find("no column matching 'Z9'"),
            std::string::npos);
  EXPECT_NE(resolve_error("base.corner5.displacement", m3).find("4 corners"), std::string::npos);
  EXPECT_NE(resolve_error("contacts.normal_force", m3).find("no 3D contact pairs"),
            std::string::npos);
  const Model m2 = build_model(load_model_file(test::thesis_model()));
  EXPECT_NE(resolve_error("base.corners.displacement", m2).find("this building is 2D"),
            std::string::npos);
  EXPECT_NE(resolve_error("roof.theta", m2).find("a peak of 3D buildings"), std::string::npos);
  EXPECT_NE(resolve_error("story1.A1.drift", m2).find("this building is 2D"), std::string::npos);
  EXPECT_EQ(resolve_error("stories.drift_ratio", m2), "no error");  // 2D as before

  EXPECT_EQ(output_unit(parse_output_selector("roof.theta")), "rad");
  EXPECT_EQ(output_unit(parse_output_selector("base.corners.displacement_x")), "m");
  EXPECT_EQ(output_unit(parse_output_selector("contacts.normal_force")), "N");
  EXPECT_EQ(output_unit(parse_output_selector("sum:contacts.friction_dissipated_energy")), "J");
  EXPECT_EQ(output_unit(parse_output_selector("max:contacts.area")), "m2");
}

// The eccentric building under the pulse pair with rigid walls east and west of its base slab
// (16.5 m square) at 0.5 cm and 10 cm, as polygon contacts labelled as the pound3d site labels
// them.
struct WalledRun {
  Model model;
  AnalysisResult result;
  GroundMotionPeaks ground;
  std::vector<double> first_impacts;  // per element, from the contact log as a sweep keeps it
};
const WalledRun& walled_run() {
  static const WalledRun run = [] {
    eccentric_run();  // writes eccentric.yaml
    const ModelConfig config = load_model_file((scratch() / "eccentric.yaml").string());
    WalledRun w;
    w.model = build_model(config);
    const int d = w.model.structures.front().level_dofs.front();
    const double half = 8.25;
    PolygonBody slab{d,
                     d + 1,
                     d + 2,
                     {0.0, 0.0},
                     ConvexPolygon{{-half, -half}, {half, -half}, {half, half}, {-half, half}},
                     340e3};
    for (const double side : {1.0, -1.0}) {
      const double gap = side > 0 ? 0.005 : 0.10;
      const double x0 = side * (half + gap), x1 = side * (half + gap + 1.0);
      PolygonBody wall{-1,
                       -1,
                       -1,
                       {0.0, 0.0},
                       ConvexPolygon{{std::min(x0, x1), -half - 1.0},
                                     {std::max(x0, x1), -half - 1.0},
                                     {std::max(x0, x1), half + 1.0},
                                     {std::min(x0, x1), half + 1.0}},
                       5e3 * (2 * half + 2.0)};
      w.model.elements.push_back(std::make_unique<PolygonContact>(
          std::string("building/base|wall ") + (side > 0 ? "east" : "west"), slab, wall,
          PolygonContactConfig{}));
    }
    const GroundMotion motion = load_ground_motion(config.ground_motion, true);
    w.ground = peaks_of(motion);
    RunOptions options = run_options(config);
    options.output.histories = true;
    ContactEventLog log(w.model, "");
    options.observer = &log;
    w.result = run_analysis(w.model, motion, options);
    w.first_impacts = log.first_impact_times(w.model);
    return w;
  }();
  return run;
}

TEST(Study3DSelectors, ContactPairsByGroupLabelAndFirstImpact) {
  const WalledRun& w = walled_run();
  const auto peak_of = [&](const std::string& selector) {
    return evaluate_output(resolve_output(parse_output_selector(selector), w.model), w.result,
                           w.ground, &w.first_impacts);
  };
  const auto output = [&](int element, const char* name) {
    const Element& e = *w.model.elements[static_cast<std::size_t>(element)];
    for (int k = 0; k < e.output_count(); ++k)
      if (e.output_name(k) == name) return w.result.element_outputs[element][k];
    ADD_FAILURE() << name;
    return Peak{};
  };
  const int east = static_cast<int>(w.model.elements.size()) - 2, west = east + 1;
  const double impacts_east = output(east, "impacts").value;
  const double impacts_west = output(west, "impacts").value;
  ASSERT_GE(impacts_east, 1.0);  // both walls are hit, the west one more than once
  ASSERT_GE(impacts_west, 2.0);
  EXPECT_EQ(peak_of("base|wall east.impacts"), impacts_east);
  EXPECT_EQ(peak_of("building/base|wall west.impacts"), impacts_west);
  EXPECT_EQ(peak_of("sum:contacts.impacts"), impacts_east + impacts_west);
  EXPECT_EQ(peak_of("sum:base|wall*.impacts"), impacts_east + impacts_west);
  EXPECT_EQ(peak_of("contacts.normal_force"),
            std::max(output(east, "normal_force").value, output(west, "normal_force").value));
  EXPECT_GT(peak_of("contacts.normal_force"), 1e5);  // N: a real impact
  EXPECT_EQ(peak_of("max:contacts.friction_dissipated_energy"),
            std::max(output(east, "friction_dissipated_energy").value,
                     output(west, "friction_dissipated_energy").value));

  // First impact, independently from the history rows: the first row where either wall's
  // impact counter is 1 is at or after it, by less than one output interval (rows at every
  // record sample; the onset itself is located inside the step; a counter misses no contact
  // shorter than a row interval, as in_contact could).
  const History& h = w.result.history;
  std::vector<std::size_t> contact_columns;
  for (std::size_t c = 0; c < h.columns.size(); ++c)
    if (h.columns[c].find("|wall ") != std::string::npos &&
        h.columns[c].find(" impacts") != std::string::npos)
      contact_columns.push_back(c);
  ASSERT_EQ(contact_columns.size(), 2u);
  double first_row = -1.0, row_interval = h.values[h.columns.size()] - h.values[0];
  for (std::size_t r = 0; r < h.rows() && first_row < 0; ++r)
    for (const std::size_t c : contact_columns)
      if (h.values[r * h.columns.size() + c] > 0.5) first_row = h.values[r * h.columns.size()];
  ASSERT_GT(first_row, 0.0);
  const double first = peak_of("contacts.first_impact_time");
  EXPECT_LE(first, first_row + 1e-12);
  EXPECT_GT(first, first_row - row_interval);
  EXPECT_LT(first, output(west, "impacts").time);  // the last impact on the west wall is later
  EXPECT_EQ(output_unit(parse_output_selector("contacts.first_impact_time")), "s");
  EXPECT_THROW(parse_output_selector("sum:contacts.first_impact_time"), std::invalid_argument);
}

TEST(Study3DSpec, AngleRangeInDegreesGives73CasesInRadians) {
  const Study s = load_study_text(
      "angles.yaml", "model: " + config("3d-thesis-building.yaml") + "\nset:\n  " + kPulsePair +
                         "\naxes:\n"
                         "  - {path: ground_motion.angle, range: {from: 0 deg, to: 360 deg, "
                         "step: 5 deg}}\noutputs: [base.displacement]\n");
  ASSERT_EQ(s.axes.size(), 1u);
  EXPECT_EQ(s.axes[0].name, "angle");  // what isopound-post polar looks for
  ASSERT_EQ(s.axes[0].levels.size(), 73u);
  EXPECT_EQ(s.case_count(), 73);
  const CaseBuilder builder(s);
  for (const int k : {0, 1, 9, 27, 45, 72}) {
    // Exactly the angle a model file with "<5k> deg" reads (the cases are written in degrees).
    const double expected = parse_quantity(std::to_string(5 * k) + " deg").si;
    const Level& level = s.axes[0].levels[static_cast<std::size_t>(k)];
    EXPECT_TRUE(level.numeric);
    EXPECT_EQ(level.si, expected) << k;
    EXPECT_EQ(builder.input_of(k).config.ground_motion.angle, expected) << k;
    EXPECT_NEAR(expected, k * 5.0 * std::numbers::pi / 180.0, 1e-15) << k;
  }
  // Each angle is its own ground motion (the pair rotated), and its own model.
  EXPECT_NE(builder.input_of(1).motion_key, builder.input_of(2).motion_key);
  EXPECT_EQ(builder.input_of(3).config.ground_motion.components.size(), 2u);
}

TEST(Study3DSpec, QwEccentricityAndPointValuedAxesReachTheBuilding) {
  const Study s = load_study_text(
      "axes3d.yaml", "model: " + config("3d-thesis-building.yaml") + "\nset:\n  " + kPulsePair +
                         "\naxes:\n"
                         "  - {name: QW, path: \"structures[0].bearing.QW\", values: [5 %, 10 %]}\n"
                         "  - name: e\n"
                         "    path: structures[0].eccentricity\n"
                         "    values:\n"
                         "      - [0 m, 0 m]\n"
                         "      - [0.825 m, -1.65 m]\n"
                         "outputs: [base.displacement, roof.theta]\n");
  ASSERT_EQ(s.case_count(), 4);
  EXPECT_FALSE(s.axes[1].levels[1].numeric);
  EXPECT_EQ(s.axes[1].levels[1].label, "[0.825 m, -1.65 m]");
  const CaseBuilder builder(s);
  const ModelConfig last = builder.input_of(3).config;
  ASSERT_EQ(last.structures3d.size(), 1u);
  EXPECT_DOUBLE_EQ(last.structures3d[0].bearing.strength_ratio, 0.10);
  EXPECT_DOUBLE_EQ(last.structures3d[0].base.eccentricity.x, 0.825);
  EXPECT_DOUBLE_EQ(last.structures3d[0].storeys[2].floor.eccentricity.y, -1.65);
  EXPECT_DOUBLE_EQ(builder.input_of(0).config.structures3d[0].storeys[0].floor.eccentricity.x, 0.0);
}

TEST(Study3DSpec, AnUnquotedListIndexInAFlowMapGetsAHint) {
  try {
    load_study_text("flow.yaml",
                    "model: " + config("3d-thesis-building.yaml") +
                        "\naxes:\n  - {path: structures[0].bearing.QW, values: [5 %]}\n");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("flow.yaml:3:"), std::string::npos) << what;
    EXPECT_NE(what.find("quote a path with a list index"), std::string::npos) << what;
  }
}

TEST(Study3DSpec, NeighbourStoreysAxisReachesTheAdjacentBuilding) {
  std::string model = test::read_file(config("3d-thesis-building.yaml"));
  model = model.substr(model.find("structures:"));
  model = model.substr(0, model.find("ground_motion:")) +
          "  - name: east-neighbour\n"
          "    isolated: false\n"
          "    adjacent: {to: building, side: east, gap: 45 cm}\n"  // clear of the 45 cm columns
          "    grid: {bays_x: [5.5 m, 5.5 m, 5.5 m], bays_y: [5.5 m, 5.5 m, 5.5 m]}\n"
          "    columns: {section: [35 cm, 35 cm], E: 30 GPa, nu: 0.2}\n"
          "    storeys: {count: 2, height: 3.2 m, mass: 340 t, roof_mass: 250 t}\n"
          "    damping: {type: rayleigh, ratios: [5 %, 5 %], modes: [1, 3]}\n";
  test::write_file(scratch() / "neighbour.yaml", model);
  const Study s = load_study_text(
      "neighbour-study.yaml",
      "model: neighbour.yaml\nset:\n  " + std::string(kPulsePair) +
          "\naxes:\n  - {name: neighbour_storeys, path: \"structures[1].storeys.count\", values: "
          "[2, 3, 4]}\noutputs: [\"building/floor 1|east-neighbour*.impacts\", "
          "sum:contacts.impacts]\n");
  const CaseBuilder builder(s);
  for (int k = 0; k < 3; ++k) {
    const ModelConfig c = builder.input_of(k).config;
    ASSERT_EQ(c.structures3d.size(), 2u);
    EXPECT_EQ(c.structures3d[1].storeys.size(), static_cast<std::size_t>(k + 2));
  }
  const ValidatedStudy v = validate_study(s, 1);  // the pair patterns resolve on every case
  EXPECT_EQ(v.distinct_models, 3);
}

TEST(Study3DSpec, RecordPairsSetLAndTOfTheModel) {
  ISOPOUND_REQUIRE_RECORDS();
  const std::string records = test::records_dir().string();
  // The base model runs the pulse pair: a pair replaces it.
  const Study s = load_study_text(
      "pairs.yaml", "model: " + config("3d-thesis-building.yaml") + "\nset:\n  " + kPulsePair +
                        "\nrecords:\n"
                        "  - {name: NGA, folder: " +
                        records +
                        ", L: RSN1084_NORTHR_SCS142.AT2, T: RSN1084_NORTHR_SCS052.AT2}\n"
                        "  - {folder: " +
                        records +
                        ", L: SCS142.AT2, T: {file: SCS052.AT2, scale: 0.5}, scale: 2}\n"
                        "  - {folder: " +
                        records + ", glob: \"RSN1084_*.AT2\", pairs: rsn, swap: true}\n" +
                        "outputs: [base.displacement, ground.pga]\n");
  ASSERT_EQ(s.axes.size(), 1u);
  EXPECT_EQ(s.axes[0].name, "record");
  ASSERT_EQ(s.axes[0].levels.size(), 3u);
  EXPECT_EQ(s.axes[0].levels[0].label, "NGA");
  EXPECT_EQ(s.axes[0].levels[1].label, "SCS142+SCS052");
  EXPECT_EQ(s.axes[0].levels[2].label, "RSN1084");  // pairs: rsn, named by the RSN
  EXPECT_EQ(s.statistics.size(), 1u);               // over the record pairs by default
  const CaseBuilder builder(s);
  const GroundMotionConfig g = builder.input_of(0).config.ground_motion;
  ASSERT_EQ(g.components.size(), 2u);
  EXPECT_FALSE(g.components[0].use_pulse);
  EXPECT_EQ(fs::path(g.components[0].record_path).filename(), "RSN1084_NORTHR_SCS142.AT2");
  EXPECT_EQ(fs::path(g.components[1].record_path).filename(), "RSN1084_NORTHR_SCS052.AT2");
  EXPECT_NEAR(g.angle, 30.0 * std::numbers::pi / 180.0, 1e-15);  // the model's angle is kept
  const GroundMotionConfig h = builder.input_of(1).config.ground_motion;
  EXPECT_DOUBLE_EQ(h.components[0].read.scale, 2.0);  // the pair's scale
  EXPECT_DOUBLE_EQ(h.components[1].read.scale, 0.5);  // T's own wins
  // By RSN the files pair in name order, SCS052 then SCS142; swap makes SCS142 the L component.
  const GroundMotionConfig r = builder.input_of(2).config.ground_motion;
  EXPECT_EQ(fs::path(r.components[0].record_path).filename(), "RSN1084_NORTHR_SCS142.AT2");
  EXPECT_EQ(fs::path(r.components[1].record_path).filename(), "RSN1084_NORTHR_SCS052.AT2");
  EXPECT_EQ(builder.identity(0), builder.identity(2));  // the same pair as the first entry
  // Each pair is read once, as two components.
  const ValidatedStudy v = validate_study(s, 1);
  ASSERT_EQ(v.motions.size(), 2u);  // entries 0 and 2 are one motion, computed once
  EXPECT_EQ(v.distinct_models, 2);
  const GroundMotion& m = v.motions.at(builder.input_of(0).motion_key)->motion;
  EXPECT_EQ(m.acceleration.size(), m.acceleration_y.size());
  EXPECT_EQ(m.acceleration.size(), 8773u);  // NPTS of both NGA-West2 files
}

TEST(Study3DSpec, MalformedRecordPairsNameLineAndKey) {
  ISOPOUND_REQUIRE_RECORDS();
  const std::string head = "model: " + config("3d-thesis-building.yaml") + "\nrecords:\n";
  const std::string records = test::records_dir().string();
  struct Bad {
    const char* name;
    std::string records;
    const char* where;
    const char* what;
  };
  const Bad cases[] = {
      {"missing_t", "  - {L: " + records + "/SCS142.AT2, name: x}\n", "3:5: records[0]",
       "needs both components, L and T"},
      {"pair_and_file",
       "  - {L: " + records + "/SCS142.AT2, T: " + records + "/SCS052.AT2, file: a.AT2}\n",
       "records[0].file", "belongs to single records"},
      {"missing_file", "  - {L: " + records + "/SCS142.AT2, T: " + records + "/nope.AT2}\n",
       "records[0].T", "nope.AT2' not found"},
      {"name_on_single", "  - {file: " + records + "/SCS142.AT2, name: x}\n", "records[0].name",
       "labels a record pair"},
      {"unpaired_rsn", "  - {folder: " + records + ", glob: \"RSN*.AT2\", pairs: rsn}\n",
       "records[0].glob", "'RSN1605' has 1: RSN1605_DUZCE_DZC270.AT2"},
      {"pairs_how", "  - {folder: " + records + ", glob: \"RSN*.AT2\", pairs: station}\n",
       "records[0].pairs", "station"},
      {"single_on_3d", "  - " + records + "/SCS142.AT2\n", "3:5: records[0]",
       "its records are pairs"},
      {"swap_single", "  - {file: " + records + "/SCS142.AT2, swap: true}\n", "records[0].swap",
       "goes with 'pairs: rsn'"},
  };
  for (const Bad& bad : cases) {
    try {
      load_study_text(std::string(bad.name) + ".yaml", head + bad.records);
      ADD_FAILURE() << bad.name << ": no error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(bad.name + std::string(".yaml:")), std::string::npos) << what;
      EXPECT_NE(what.find(bad.where), std::string::npos) << bad.name << ": " << what;
      EXPECT_NE(what.find(bad.what), std::string::npos) << bad.name << ": " << what;
    }
  }
}

// 8 incidence angles of the eccentric building under the pulse pair, with peaks of every kind.
std::string angle_study(const std::string& model) {
  return "name: angles3d\nmodel: " + model + "\nset:\n  " + kPulsePair + R"(
axes:
  - {path: ground_motion.angle, range: {from: 0 deg, to: 315 deg, step: 45 deg}}
outputs:
  u_base: base.displacement
  u_corners: base.corners.displacement
  theta_roof: roof.theta
  drift_corners: stories.corners.drift_ratio
  a_floors: floors.points.absolute_acceleration
  bearing: bearing*.deformation
statistics:
  - {over: [angle]}
)";
}

// XY-5 (walls on four sides) closed to 5 cm under the pulse pair, to 3.3 s: every angle pounds
// (first impact near 2.95 s, 7 impacts by 3.3 s); 4 angles.
std::string pounding_study() {
  return "name: xy5pulse\nmodel: " + config("3d-xy5.yaml") + "\nset:\n  " + kPulsePair + R"(
  structures[0].walls.gap: 5 cm
  analysis.t_end: 3.3 s
axes:
  - {path: ground_motion.angle, range: {from: 0 deg, to: 315 deg, step: 105 deg}}
outputs:
  u_corners: base.corners.displacement
  theta_roof: roof.theta
  drift_corners: stories.corners.drift_ratio
  a_corners: floors.corners.absolute_acceleration
  F_N: contacts.normal_force
  F_T: contacts.tangential_force
  impacts: sum:contacts.impacts
  first_impact: contacts.first_impact_time
  first_east: base|wall east.first_impact_time
  E_friction: sum:contacts.friction_dissipated_energy
statistics:
  - {over: [angle]}
)";
}

TEST(Study3DSweep, AngleSweepTablesAreByteIdenticalForOneAndTwoThreads) {
  // With pounding on four walls: the case most sensitive to any difference between threads.
  const fs::path dir = test::study_scratch("angles3d");
  test::write_file(dir / "study.yaml", pounding_study());
  for (const char* jobs : {"1", "2"}) {
    const fs::path out = dir / (std::string(1, 'j') += jobs);  // j1, j2
    const std::string db = out.string() + ".db";
    const auto r = test::run_isopound("sweep '" + (dir / "study.yaml").string() + "' -q -j " +
                                      jobs + " --db '" + db + "'");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto e = test::run_isopound("export '" + db + "' -o '" + out.string() + "'");
    ASSERT_EQ(e.exit_code, 0) << e.output;
  }
  for (const char* table : {"runs.csv", "statistics.csv", "units.csv"}) {
    const std::string one = test::read_file(dir / "j1" / table);
    EXPECT_FALSE(one.empty()) << table;
    EXPECT_TRUE(one == test::read_file(dir / "j2" / table)) << table << " differs";
  }
  const std::string runs = test::read_file(dir / "j1" / "runs.csv");
  EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 5);
  EXPECT_EQ(runs.find(",failed,"), std::string::npos) << runs;
  EXPECT_EQ(runs.substr(0, runs.find('\n')),
            "case_id,angle,status,steps,u_corners,theta_roof,drift_corners,a_corners,F_N,F_T,"
            "impacts,first_impact,first_east,E_friction,error");
  const std::string units = test::read_file(dir / "j1" / "units.csv");
  EXPECT_NE(units.find("runs,theta_roof,rad"), std::string::npos) << units;
  fs::remove_all(dir);  // kept when an assertion failed above
}

TEST(Study3DSweep, ACaseIsTheRunOfItsModelFile) {
  // The study's case at 105 deg and a run of the model file with "angle: 105 deg" are the same
  // analysis (the angle is written in degrees, the contact log kept): the table holds exactly
  // the numbers of summary.json, also where pounding makes 1e-12 differences grow.
  const Study s = load_study_text("xy5pulse.yaml", pounding_study());
  const ValidatedStudy validated = validate_study(s, 1);
  const RunRecord record = CaseRunner(s, validated).run(1);
  ASSERT_TRUE(record.ok) << record.error;
  ASSERT_EQ(record.values.size(), s.outputs.size());
  const auto column = [&](const std::string& name) {
    for (std::size_t k = 0; k < s.outputs.size(); ++k)
      if (s.outputs[k].column == name) return record.values[k];
    ADD_FAILURE() << name;
    return 0.0;
  };

  std::string text = test::read_file(config("3d-xy5.yaml"));
  text.replace(text.find("gap: 20 cm"), 10, "gap: 5 cm");
  std::string motion = kPulsePair;
  motion.replace(motion.find("angle: 30 deg"), 13, "angle: 105 deg");
  text = text.substr(0, text.find("ground_motion:")) + motion + "\nanalysis: {t_end: 3.3 s}\n";
  test::write_file(scratch() / "xy5-105.yaml", text);
  const JobResult job = run_job(load_model_file((scratch() / "xy5-105.yaml").string()));
  const json contacts = contacts3d_json(job);
  ASSERT_EQ(contacts.size(), 4u);
  double impacts = 0.0, friction = 0.0, normal = 0.0, first = 1e300, first_east = -1.0;
  for (const json& c : contacts) {
    impacts += c.at("impacts").get<double>();
    friction += c.at("friction_dissipated_J").get<double>();
    normal = std::max(normal, value(c.at("normal_force")));
    if (!c.at("first_impact_time_s").is_null())
      first = std::min(first, c.at("first_impact_time_s").get<double>());
    if (c.at("label") == "building/base|wall east" && !c.at("first_impact_time_s").is_null())
      first_east = c.at("first_impact_time_s").get<double>();
  }
  ASSERT_GE(impacts, 3.0);  // 5 impacts by 3.3 s
  EXPECT_EQ(column("impacts"), impacts);
  EXPECT_EQ(column("F_N"), normal);
  EXPECT_EQ(column("first_impact"), first);
  if (first_east < 0)
    EXPECT_TRUE(std::isnan(column("first_east")));  // an empty cell: the east wall is not hit
  else
    EXPECT_EQ(column("first_east"), first_east);
  // Friction energy: the study keeps each pair's peak, the summary its final value (equal:
  // the energy only grows); the sum over the pairs in the same order.
  EXPECT_EQ(column("E_friction"), friction);
  const json summary = summary3d_json(job);
  const json& base = summary.at(0).at("levels").at(0);
  EXPECT_EQ(column("u_corners"), max_over(base.at("corners"), [](const json& c) {
              return value(c.at("displacement").at("resultant"));
            }));
}

TEST(Study3DSweep, DoublySymmetricBuildingGivesTheSamePeaksAtEveryAngle) {
  // The thesis building is doubly symmetric with isotropic (coupled) bearings: turning the
  // ground motion turns the response, so resultant peaks cannot depend on the angle and the
  // floors do not twist. A wrong rotation or component mix-up in a study would break this.
  const fs::path dir = test::study_scratch("symmetric3d");
  test::write_file(dir / "study.yaml", angle_study(config("3d-thesis-building.yaml")));
  const std::string db = (dir / "s.db").string();
  ASSERT_EQ(
      test::run_isopound("sweep '" + (dir / "study.yaml").string() + "' -q -j 2 --db '" + db + "'")
          .exit_code,
      0);
  const Study s = load_study_file((dir / "study.yaml").string());
  StudyStore store = StudyStore::open(db, true);
  const std::vector<RunRow> rows = store.read_runs();
  ASSERT_EQ(rows.size(), 8u);
  for (const RunRow& r : rows) {
    ASSERT_EQ(r.status, "done");
    for (std::size_t k : {0u, 1u, 3u, 4u, 5u})  // resultants: equal to round-off (1e-9)
      EXPECT_NEAR(r.values[k], rows[0].values[k], 1e-9 * rows[0].values[k]) << s.outputs[k].column;
    EXPECT_LT(r.values[2], 1e-12);  // roof twist, rad
  }
  EXPECT_GT(rows[0].values[0], 0.05);  // the pulse moves the base by decimetres
  fs::remove_all(dir);
}

}  // namespace
}  // namespace isopound

namespace isopound {
namespace {

TEST(Study3DConfigs, Xy5StudiesValidate) {
  ISOPOUND_REQUIRE_RECORDS();
  const fs::path studies = test::source_dir() / "configs" / "studies";
  const auto r = test::run_isopound("sweep '" + (studies / "3d-xy5-angles.yaml").string() +
                                    "' --dry-run -j 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("73 runs (73 distinct models, 73 ground motions)"), std::string::npos)
      << r.output;
  // The larger ones: read and checked without building their 1533 and 219 models.
  const Study gaps = load_study_file((studies / "3d-xy5-angles-gaps.yaml").string());
  EXPECT_EQ(gaps.case_count(), 73 * 21);
  ASSERT_EQ(gaps.axes.size(), 3u);  // record, angle, gap
  EXPECT_DOUBLE_EQ(gaps.axes[2].levels.front().si, 0.15);
  EXPECT_DOUBLE_EQ(gaps.axes[2].levels.back().si, 0.65);
  const CaseBuilder builder(gaps);  // angle 5 deg, gap 17.5 cm: on every side
  const ModelConfig c = builder.input_of(21 + 1).config;
  for (const double gap : c.structures3d[0].walls.gap) EXPECT_DOUBLE_EQ(gap, 0.175);
  EXPECT_EQ(c.ground_motion.angle, parse_quantity("5 deg").si);
  const Study tolerance = load_study_file((studies / "3d-xy5-angles-tolerance.yaml").string());
  EXPECT_EQ(tolerance.case_count(), 3 * 73);
}

TEST(Study3DConfigs, TutorialStudyValidates) {
  const auto r = test::run_isopound(
      "sweep '" + (test::source_dir() / "configs" / "studies" / "tutorial-3d.yaml").string() +
      "' --dry-run");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // 9 angles x 2 Q/W x 2 eccentricities; one pulse pair per angle.
  EXPECT_NE(r.output.find("36 runs (36 distinct models, 9 ground motions)"), std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace isopound
