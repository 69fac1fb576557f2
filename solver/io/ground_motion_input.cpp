// Reading `ground_motion:` into GroundMotionConfig (interface: ground_motion_input.h).
#include "solver/io/ground_motion_input.h"

#include <filesystem>
#include <functional>
#include <limits>

namespace isopound {
namespace {

namespace fs = std::filesystem;

constexpr int kIntMax = std::numeric_limits<int>::max();
constexpr double kMaxPulseSamples = 1e6;  // 1e6 x 8 bytes; a real pulse has ~10^4

// A record pair: L and T, each read by `read_component` (the one-component reader), at `angle`.
GroundMotionConfig read_ground_motion_pair(
    const InputNode& node,
    const std::function<GroundMotionConfig(const InputNode&)>& read_component) {
  const auto l = node.find("L");
  const auto t = node.find("T");
  if (!l || !t) {
    const std::string what =
        "a record pair needs both components L and T (an angle with one component has no meaning)";
    if (const auto angle = node.find("angle")) angle->fail(what);
    node.fail(what);
  }
  node.expect_keys({"L", "T", "angle", "extra_time"});
  GroundMotionConfig g;
  node.read_quantity("extra_time", dim::kTime, Bound::kNonNegative, g.extra_time);
  node.read_angle("angle", g.angle);
  for (const InputNode& c : {*l, *t}) {
    if (c.has("extra_time"))
      c.find("extra_time")->fail("give extra_time once, at ground_motion, for the pair");
    g.components.push_back(read_component(c));
  }
  // Components of different units: an error (a pair is one measurement; a unit mismatch is
  // almost always a mistake). PEER files are in g.
  const auto unit_of = [](const GroundMotionConfig& c) {
    return c.use_pulse ? AccelerationUnit::kMetrePerSecond2 : c.read.unit;
  };
  if (!g.components[0].use_pulse && !g.components[1].use_pulse &&
      unit_of(g.components[0]) != unit_of(g.components[1]))
    t->fail_at_key("unit", "the T component's unit differs from L's: give both in the same unit");
  g.use_pulse = false;
  return g;
}

PulseParameters read_pulse(const InputNode& node) {
  node.expect_keys({"amplitude", "period", "gamma", "phase", "t_peak", "duration", "dt"});
  PulseParameters p;
  node.read_quantity("amplitude", dim::kVelocity, Bound::kNonZero, p.amplitude);
  node.read_quantity("period", dim::kTime, Bound::kPositive, p.period);
  if (const auto gamma = node.find("gamma")) {
    p.gamma = gamma->number();
    if (!(p.gamma > 1.0)) gamma->fail("must be > 1 (got '" + gamma->string() + "')");
  }
  node.read_angle("phase", p.phase);  // "90 deg" or "1.57 rad"
  node.read_quantity("t_peak", dim::kTime, Bound::kNonNegative, p.t_peak);
  node.read_quantity("duration", dim::kTime, Bound::kPositive, p.duration);
  node.read_quantity("dt", dim::kTime, Bound::kPositive, p.dt);
  const auto dt = node.find("dt");
  const InputNode& where = dt ? *dt : node;
  if (p.dt > p.duration) where.fail("the step dt is longer than the duration of the pulse");
  if (p.duration / p.dt > kMaxPulseSamples)
    where.fail("duration / dt gives more than 1e6 samples: increase dt or shorten the duration");
  return p;
}

}  // namespace

GroundMotionConfig read_ground_motion(const InputNode& node, const std::string& base_dir) {
  using Format = RecordReadOptions::Format;
  for (std::string_view key : kPairKeys)  // a record pair (3D)
    if (node.has(key))
      return read_ground_motion_pair(
          node, [&](const InputNode& c) { return read_ground_motion(c, base_dir); });
  node.expect_keys(
      {"record", "format", "column", "time_column", "dt", "unit", "scale", "extra_time", "pulse"});
  GroundMotionConfig g;
  node.read_quantity("extra_time", dim::kTime, Bound::kNonNegative, g.extra_time);
  const auto record = node.find("record");
  if (!record) {
    for (const char* key : {"format", "column", "time_column", "dt", "unit", "scale"})
      if (node.written(key))
        node.find(key)->fail(
            "applies to a record file, but no 'record' is given (the built-in pulse is used)");
    if (const auto pulse = node.find("pulse"))
      g.pulse = read_pulse(*pulse);
    else
      node.note_default("pulse", "the built-in near-fault pulse (amplitude 1 m/s, period 2 s)");
    return g;
  }
  if (const auto pulse = node.find("pulse"))
    pulse->fail("give either 'record' or 'pulse', not both");
  const std::string path = record->string();
  if (path.empty()) record->fail("must not be empty");
  fs::path resolved(path);
  if (resolved.is_relative() && !base_dir.empty()) resolved = fs::path(base_dir) / resolved;
  g.record_path = resolved.lexically_normal().string();
  g.use_pulse = false;

  RecordReadOptions& read = g.read;
  const auto format = node.find("format");
  if (format)
    read.format = format->choice<Format>(
        {{"auto", Format::kAuto}, {"peer", Format::kPeer}, {"columns", Format::kColumns}});
  // What `auto` will find decides which keys apply (a missing file is reported when it is read).
  Format effective = read.format;
  if (effective == Format::kAuto)
    effective = sniff_record_format(g.record_path).value_or(Format::kAuto);
  node.read_number("scale", Bound::kNonZero, read.scale);
  if (effective == Format::kPeer) {
    for (const char* key : {"column", "time_column", "dt", "unit"})
      if (node.written(key))
        node.find(key)->fail(
            "not used: a PEER .AT2 record carries its own NPTS/DT and states its unit in its "
            "header (use 'scale' to change the amplitude); a PEER record uses: record, format, "
            "scale, extra_time");
    return g;
  }
  // Unknown (the file cannot be read now; reading it later reports why): the column keys are
  // read as given, without requiring any.
  const bool known = effective == Format::kColumns;
  // Read as columns only because no NPTS/DT line was found: say so when a column key is missing.
  const std::string as_columns =
      known && !format ? " (no NPTS/DT header line was found in '" +
                             fs::path(g.record_path).filename().string() +
                             "', so it is read as a plain column file, which needs it; write "
                             "format: columns to say so, or check the PEER header)"
                       : "";
  for (const char* key : {"dt", "unit"})
    if (!as_columns.empty() && !node.written(key) &&
        !(std::string_view(key) == "dt" && node.written("time_column")))
      node.fail_at_key(key, "missing required key '" + std::string(key) + "'" + as_columns);
  node.read_integer("column", 0, kIntMax, read.column);
  const auto time_column = node.find("time_column");
  if (time_column) {
    read.time_column = time_column->integer(0, kIntMax);
    if (read.time_column == read.column)
      time_column->fail("is the same as 'column' (" + std::to_string(read.column) + ")");
    if (node.written("dt"))
      node.find("dt")->fail("give either 'dt' or 'time_column' (dt is then read from the times)");
  } else if (known || node.written("dt")) {
    read.dt = node.required("dt").quantity(dim::kTime, Bound::kPositive);
  }
  // A column file says nothing about its unit: a wrong guess scales everything by 100 or 9.81.
  if (known || node.written("unit")) {
    const InputNode unit = node.required("unit");
    read.unit =
        unit.choice<AccelerationUnit>({{"g", AccelerationUnit::kG},
                                       {"m/s2", AccelerationUnit::kMetrePerSecond2},
                                       {"m/s^2", AccelerationUnit::kMetrePerSecond2},
                                       {"cm/s2", AccelerationUnit::kCentimetrePerSecond2},
                                       {"cm/s^2", AccelerationUnit::kCentimetrePerSecond2}});
  }
  return g;
}

}  // namespace isopound
