// Ground motions: PEER .AT2 and plain-column record readers, peak ground motion from exact
// integration of piecewise-linear acceleration, and the Mavroeidis-Papageorgiou pulse.
#include "solver/excitation/ground_motion.h"

#include "solver/core/constants.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>

namespace isopound {

namespace {

constexpr std::size_t kAutoHeaderLines = 40;    // kAuto looks for NPTS/DT only this far
constexpr long long kMaxSamples = 100'000'000;  // guards against absurd NPTS / duration / dt
constexpr const char* kHeaderForms =
    "expected 'NPTS= 8773, DT= .0050 SEC' or '7997 0.0050 NPTS, DT'";

std::string fmt(double x) {
  std::ostringstream os;
  os.precision(10);
  os << x;
  return os.str();
}

constexpr std::size_t kMaxLineBytes = 1 << 20;        // no record line is a megabyte long
constexpr std::uintmax_t kMaxFileBytes = 4ull << 30;  // 4 GiB: 1e8 samples of ~40 characters
constexpr std::size_t kMaxPeerHeaderLines = 10000;    // format: peer looks this far for NPTS

// A record file read line by line (without '\n' or "\r\n"), so memory holds the samples and
// not the text. A file that never ends (/dev/zero), a line longer than 1 MiB or more than 4 GiB
// of text is refused with a RecordError rather than read until memory runs out.
class LineReader {
 public:
  explicit LineReader(const std::string& path) : path_(path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
      throw RecordError(path, 0, "is a directory, not a record file");
    if (!std::filesystem::exists(path, ec))
      throw RecordError(path, 0, "cannot open file (missing or unreadable)");
    if (std::filesystem::is_regular_file(path, ec)) {
      const std::uintmax_t size = std::filesystem::file_size(path, ec);
      if (!ec && size > kMaxFileBytes)
        throw RecordError(path, 0,
                          "the file has " + std::to_string(size >> 20) +
                              " MiB: more than the 4 GiB a record of 1e8 samples needs; is it "
                              "a record?");
      if (!ec) size_ = size;
    }
    in_.open(path, std::ios::binary);
    if (!in_) throw RecordError(path, 0, "cannot open file (missing or unreadable)");
  }
  // The next line, or false at the end; line_number() is then its 1-based number. The file is
  // read in blocks and a line found with memchr (a character at a time through the stream cost
  // more than parsing the numbers).
  bool next(std::string& line) {
    line.clear();
    bool any = false;
    while (true) {
      if (at_ == end_ && !fill()) break;
      any = true;
      const char* start = buffer_.data() + at_;
      const std::size_t left = end_ - at_;
      const char* newline = static_cast<const char*>(std::memchr(start, '\n', left));
      const std::size_t length = newline ? static_cast<std::size_t>(newline - start) : left;
      const std::size_t used = newline ? length + 1 : length;
      bytes_ += used;
      if (bytes_ > kMaxFileBytes)
        throw RecordError(path_, line_ + 1,
                          "more than 4 GiB read and the file goes on: not a record file");
      line.append(start, length);
      at_ += used;
      if (line.size() > kMaxLineBytes)
        throw RecordError(path_, line_ + 1,
                          "a line longer than 1 MiB: not a text record (binary data or a "
                          "device such as /dev/zero?)");
      if (newline) break;
    }
    if (!any) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    ++line_;
    return true;
  }
  int line_number() const { return line_; }
  std::uintmax_t size() const { return size_; }  // bytes of a regular file, else 0

 private:
  // The next block of the file into buffer_; false at the end.
  bool fill() {
    if (buffer_.empty()) buffer_.resize(kBlockBytes);
    in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    if (in_.bad()) throw RecordError(path_, line_ + 1, "read error");
    at_ = 0;
    end_ = static_cast<std::size_t>(in_.gcount());
    return end_ > 0;
  }

  static constexpr std::size_t kBlockBytes = 1 << 13;
  std::string path_;
  std::ifstream in_;
  std::vector<char> buffer_;
  std::size_t at_ = 0, end_ = 0;  // the unread bytes of buffer_
  int line_ = 0;
  std::uintmax_t bytes_ = 0;
  std::uintmax_t size_ = 0;
};

// Calls fn(line_number, line) for the buffered head lines from index `from`, then for the rest of
// the file; fn returns false to stop.
template <typename Fn>
void for_each_line(const std::vector<std::string>& head, std::size_t from, LineReader& reader,
                   Fn fn) {
  for (std::size_t i = from; i < head.size(); ++i)
    if (!fn(static_cast<int>(i + 1), std::string_view(head[i]))) return;
  std::string line;
  while (reader.next(line))
    if (!fn(reader.line_number(), std::string_view(line))) return;
}

// The first `count` lines (fewer at the end of the file).
std::vector<std::string> read_head(LineReader& reader, std::size_t count) {
  std::vector<std::string> lines;
  std::string line;
  while (lines.size() < count && reader.next(line)) lines.push_back(line);
  return lines;
}

// std::isspace of the "C" locale (isopound never sets another), without the call per character.
bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

bool is_blank(std::string_view s) {
  return std::all_of(s.begin(), s.end(), is_space);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// Whitespace-separated tokens; `extra` adds separators (',' and ';' for column files).
std::vector<std::string_view> tokens_of(std::string_view line, std::string_view extra = {}) {
  auto is_sep = [&](char c) {
    return is_space(c) || (!extra.empty() && extra.find(c) != std::string_view::npos);
  };
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_sep(line[i])) ++i;
    std::size_t j = i;
    while (j < line.size() && !is_sep(line[j])) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

enum class Parsed { kOk, kNotANumber, kNotFinite };

// Locale-independent; accepts "-.4981725E-02", "+1e3", "2.9638835e-001". The whole token
// must be consumed, so "1.0-0.5" (glued Fortran fields) is rejected rather than half read.
Parsed parse_number(std::string_view tok, double& out) {
  std::string_view body = tok;
  if (body.size() > 1 && body.front() == '+' && body[1] != '-' && body[1] != '+')
    body.remove_prefix(1);
  if (body.empty()) return Parsed::kNotANumber;
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(body.data(), body.data() + body.size(), value);
  if (ptr != body.data() + body.size()) return Parsed::kNotANumber;
  if (ec == std::errc::invalid_argument) return Parsed::kNotANumber;
  if (ec == std::errc::result_out_of_range) {
    // Overflow is not finite; underflow is a legitimately tiny value.
    value = std::strtod(std::string(body).c_str(), nullptr);
  }
  if (!std::isfinite(value)) return Parsed::kNotFinite;
  out = value;
  return Parsed::kOk;
}

// Parses a data token or throws RecordError naming the line and the token.
double number_or_throw(const std::string& path, int line, std::string_view tok,
                       std::string_view hint = {}) {
  double value = 0.0;
  switch (parse_number(tok, value)) {
    case Parsed::kOk:
      return value;
    case Parsed::kNotFinite:
      throw RecordError(path, line,
                        "value '" + std::string(tok) + "' is not finite (NaN or infinity)");
    case Parsed::kNotANumber:
      break;
  }
  throw RecordError(
      path, line,
      "non-numeric value '" + std::string(tok) + "' (expected a number)" + std::string(hint));
}

bool all_numeric(std::string_view line) {
  const auto toks = tokens_of(line);
  if (toks.empty()) return false;
  double ignored = 0.0;
  return std::all_of(toks.begin(), toks.end(),
                     [&](std::string_view t) { return parse_number(t, ignored) == Parsed::kOk; });
}

bool contains_nocase(std::string_view text, std::string_view word) {
  auto it = std::search(text.begin(), text.end(), word.begin(), word.end(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  });
  return it != text.end();
}

struct PeerHeader {
  std::size_t index = 0;  // 0-based line index of the NPTS/DT line
  std::string npts_text, dt_text;
};

// Hand-written matchers for the two header patterns of records/README.md section 3:
//   NPTS\s*=\s*(\d+)\s*,\s*DT\s*=\s*([0-9.Ee+-]+)   (case-insensitive, anywhere in the line)
//   ^\s*(\d+)\s+([0-9.Ee+-]+)\s+NPTS\s*,\s*DT        (case-insensitive)
// Not std::regex: libstdc++ matches recursively and can overflow the stack on long lines.
class Cursor {
 public:
  explicit Cursor(std::string_view s, std::size_t pos = 0) : s_(s), pos_(pos) {}
  std::size_t spaces() {
    const std::size_t start = pos_;
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    return pos_ - start;
  }
  bool literal(std::string_view word) {  // case-insensitive
    if (s_.size() - pos_ < word.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(s_[pos_ + i])) !=
          std::tolower(static_cast<unsigned char>(word[i])))
        return false;
    pos_ += word.size();
    return true;
  }
  std::string run(std::string_view allowed) {  // longest run of characters from `allowed`
    const std::size_t start = pos_;
    while (pos_ < s_.size() && allowed.find(s_[pos_]) != std::string_view::npos) ++pos_;
    return std::string(s_.substr(start, pos_ - start));
  }

 private:
  std::string_view s_;
  std::size_t pos_;
};

constexpr std::string_view kDigits = "0123456789";
constexpr std::string_view kRealChars = "0123456789.Ee+-";
using NptsDt = std::pair<std::string, std::string>;

std::optional<NptsDt> match_names_first(std::string_view line) {
  for (std::size_t at = 0; at + 4 <= line.size(); ++at) {
    Cursor c(line, at);
    if (!c.literal("npts")) continue;
    c.spaces();
    if (!c.literal("=")) continue;
    c.spaces();
    std::string npts = c.run(kDigits);
    if (npts.empty()) continue;
    c.spaces();
    if (!c.literal(",")) continue;
    c.spaces();
    if (!c.literal("dt")) continue;
    c.spaces();
    if (!c.literal("=")) continue;
    c.spaces();
    std::string dt = c.run(kRealChars);
    if (dt.empty()) continue;
    return NptsDt{std::move(npts), std::move(dt)};
  }
  return std::nullopt;
}

std::optional<NptsDt> match_values_first(std::string_view line) {
  Cursor c(line);
  c.spaces();
  std::string npts = c.run(kDigits);
  if (npts.empty() || c.spaces() == 0) return std::nullopt;
  std::string dt = c.run(kRealChars);
  if (dt.empty() || c.spaces() == 0) return std::nullopt;
  if (!c.literal("npts")) return std::nullopt;
  c.spaces();
  if (!c.literal(",")) return std::nullopt;
  c.spaces();
  if (!c.literal("dt")) return std::nullopt;
  return NptsDt{std::move(npts), std::move(dt)};
}

// First line (of the first `limit`) in either NPTS/DT form.
std::optional<PeerHeader> find_peer_header(const std::vector<std::string>& lines,
                                           std::size_t limit) {
  const std::size_t n = std::min(limit, lines.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!contains_nocase(lines[i], "npts")) continue;
    auto m = match_names_first(lines[i]);
    if (!m) m = match_values_first(lines[i]);
    if (m) return PeerHeader{i, std::move(m->first), std::move(m->second)};
  }
  return std::nullopt;
}

// "VELOCITY TIME SERIES", "DISPLACEMENT TIME HISTORY": line 3 of PEER .VT2/.DT2 files.
bool names_velocity_or_displacement(std::string_view line) {
  std::vector<std::string> words;
  for (std::string_view t : tokens_of(line)) {
    std::string w(t);
    std::transform(w.begin(), w.end(), w.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
    words.push_back(std::move(w));
  }
  for (std::size_t i = 0; i + 2 < words.size(); ++i)
    if ((words[i] == "VELOCITY" || words[i] == "DISPLACEMENT") && words[i + 1] == "TIME" &&
        (words[i + 2] == "SERIES" || words[i + 2] == "HISTORY"))
      return true;
  return false;
}

// Error for a PEER file without a readable NPTS/DT line, pointing where it went wrong.
[[noreturn]] void throw_missing_header(const std::string& path,
                                       const std::vector<std::string>& lines, std::size_t limit) {
  const std::size_t n = std::min(limit, lines.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (contains_nocase(lines[i], "npts"))
      throw RecordError(
          path, static_cast<int>(i + 1),
          std::string("cannot read NPTS and DT from this header line (") + kHeaderForms + ")");
    if (all_numeric(lines[i]))
      throw RecordError(
          path, static_cast<int>(i + 1),
          std::string("data begins here but no NPTS/DT header line was found above it (") +
              kHeaderForms + ")");
  }
  throw RecordError(path, 0, std::string("no NPTS/DT header line found (") + kHeaderForms + ")");
}

// The acceleration unit a PEER header states above its NPTS/DT line, in the forms seen in real
// files (records/README.md section 3): "ACCELERATION TIME SERIES IN UNITS OF G", "... IN UNITS
// OF G. FILTER POINTS ...", "Acceleration in g", "The units are (g)".
struct HeaderUnit {
  double si = kGravity;  // m/s^2 per value
  std::string text;      // as written, "CM/S/S"; empty when the header states none
  int line = 0;          // 1-based
};

// "CM/S/S" -> 0.01 m/s^2; 0 for a unit not known.
double acceleration_unit_si(std::string unit) {
  std::transform(unit.begin(), unit.end(), unit.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
  std::string seconds;  // CM/SEC/SEC -> CM/S/S
  for (std::size_t i = 0; i < unit.size();) {
    const bool sec = unit.compare(i, 3, "SEC") == 0;
    seconds.push_back(unit[i]);
    i += sec ? 3 : 1;
  }
  unit = std::move(seconds);
  for (const std::string_view square : {"/S**2", "/S^2", "/S2"}) {  // CM/S**2 -> CM/S/S
    if (!unit.ends_with(square)) continue;
    // Replaced in place: GCC 12 at -O3 warns falsely on '+' (-Wrestrict) and, depending on
    // inlining, on resize() (-Wstringop-overflow).
    unit.replace(unit.size() - square.size(), square.size(), "/S/S");
  }
  if (unit == "G" || unit == "GS") return kGravity;
  if (unit == "GAL" || unit == "GALS" || unit == "CM/S/S") return 0.01;
  if (unit == "M/S/S") return 1.0;
  if (unit == "MM/S/S") return 0.001;
  if (unit == "IN/S/S") return 0.0254;
  if (unit == "FT/S/S") return 0.3048;
  return 0.0;
}

HeaderUnit header_unit(const std::string& path, const std::vector<std::string>& lines,
                       std::size_t header_index) {
  HeaderUnit out;
  for (std::size_t i = 0; i < header_index && i < lines.size(); ++i) {
    std::string upper = lines[i];
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
    std::size_t at = std::string::npos;
    for (const char* phrase : {"UNITS OF ", "UNITS ARE ", "ACCELERATION IN "}) {
      at = upper.find(phrase);
      if (at != std::string::npos) {
        at += std::string_view(phrase).size();
        break;
      }
    }
    if (at == std::string::npos) continue;
    std::string_view rest = trim(std::string_view(lines[i]).substr(at));
    std::size_t end = 0;
    while (end < rest.size() && !std::isspace(static_cast<unsigned char>(rest[end])) &&
           rest[end] != ',')
      ++end;
    std::string_view word = rest.substr(0, end);
    while (!word.empty() && (word.front() == '(' || word.front() == '[')) word.remove_prefix(1);
    while (!word.empty() && (word.back() == ')' || word.back() == ']' || word.back() == '.' ||
                             word.back() == ';' || word.back() == ':'))
      word.remove_suffix(1);
    out.text = std::string(word);
    out.line = static_cast<int>(i + 1);
    out.si = acceleration_unit_si(out.text);
    if (out.si == 0.0)
      throw RecordError(path, out.line,
                        "the header states the unit '" + out.text +
                            "', not an acceleration unit isopound knows (g, cm/s/s or gal, "
                            "m/s/s, mm/s/s, in/s/s, ft/s/s)");
    return out;
  }
  return out;
}

GroundMotion read_peer(const std::string& path, const std::vector<std::string>& lines,
                       LineReader& reader, const PeerHeader& header, double scale) {
  const int header_line = static_cast<int>(header.index + 1);

  // A PEER velocity/displacement file (.VT2/.DT2) has the same layout: refuse it.
  for (std::size_t i = 0; i < header.index; ++i)
    if (names_velocity_or_displacement(lines[i]))
      throw RecordError(path, static_cast<int>(i + 1),
                        "this PEER file holds velocity or displacement, not acceleration");
  const HeaderUnit unit = header_unit(path, lines, header.index);
  const double factor = unit.si * scale;

  long long npts = 0;
  {
    const std::string& s = header.npts_text;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), npts);
    if (ec != std::errc() || ptr != s.data() + s.size() || npts > kMaxSamples)
      throw RecordError(path, header_line, "NPTS = " + s + " is not a usable number of points");
    if (npts <= 0)
      throw RecordError(path, header_line, "NPTS = " + s + ": the record has no points");
  }
  double dt = 0.0;
  if (parse_number(header.dt_text, dt) != Parsed::kOk)
    throw RecordError(path, header_line, "DT value '" + header.dt_text + "' is not a number");
  if (!(dt > 0.0))
    throw RecordError(path, header_line,
                      "DT = " + header.dt_text + " s: the time step must be > 0");

  GroundMotion motion;
  motion.name = std::filesystem::path(path).stem().string();
  motion.dt = dt;
  const std::string file = std::filesystem::path(path).filename().string();
  if (unit.text.empty())
    motion.unit_note = file + ": the header states no unit: read as g (the PEER convention)";
  else if (unit.si != kGravity)
    motion.unit_note = file + ": header line " + std::to_string(unit.line) + " says units of " +
                       unit.text + ": converted to m/s^2 (x " + fmt(unit.si) + " per value)";
  // A bogus NPTS must not reserve gigabytes before the data prove it: a value takes at least
  // two bytes of the file (a digit and a separator).
  const long long fits = reader.size() > 0 ? static_cast<long long>(reader.size() / 2) : 1LL << 20;
  motion.acceleration.reserve(static_cast<std::size_t>(std::min(npts, fits)));
  int last_value_line = header_line;
  for_each_line(lines, header.index + 1, reader, [&](int line_no, std::string_view text) {
    const std::string_view line = trim(text);
    if (line.empty()) return true;
    if (line.starts_with("***")) {
      // "*** Begin data ***" before the values is skipped; "*** End Data ***" ends them.
      return motion.acceleration.empty();
    }
    for (std::string_view tok : tokens_of(line)) {
      const double g = number_or_throw(path, line_no, tok);
      if (static_cast<long long>(motion.acceleration.size()) == npts)
        throw RecordError(path, line_no,
                          "more values than NPTS = " + std::to_string(npts) + " (value " +
                              std::to_string(npts + 1) + " is on this line; header line " +
                              std::to_string(header_line) + ")");
      motion.acceleration.push_back(g * factor);
    }
    last_value_line = line_no;
    return true;
  });
  if (static_cast<long long>(motion.acceleration.size()) < npts)
    throw RecordError(path, last_value_line,
                      "truncated record: found " + std::to_string(motion.acceleration.size()) +
                          " values but NPTS = " + std::to_string(npts) + " (header line " +
                          std::to_string(header_line) + ")");
  return motion;
}

double unit_factor(AccelerationUnit unit) {
  switch (unit) {
    case AccelerationUnit::kG:
      return kGravity;
    case AccelerationUnit::kMetrePerSecond2:
      return 1.0;
    case AccelerationUnit::kCentimetrePerSecond2:
      return 0.01;
  }
  return 1.0;
}

GroundMotion read_columns(const std::string& path, const std::vector<std::string>& lines,
                          LineReader& reader, const RecordReadOptions& options,
                          std::string_view hint) {
  if (options.column < 0)
    throw RecordError(path, 0, "column index " + std::to_string(options.column) + " must be >= 0");
  if (options.time_column < -1)
    throw RecordError(path, 0,
                      "time column index " + std::to_string(options.time_column) +
                          " must be >= 0 (or -1 for none)");
  if (options.time_column == options.column)
    throw RecordError(path, 0,
                      "the time column and the acceleration column are both column " +
                          std::to_string(options.column));
  const bool has_time = options.time_column >= 0;
  const double factor = unit_factor(options.unit) * options.scale;

  std::vector<double> accel;
  // Time column: checked row by row against the first step, so nothing but the samples is kept.
  double first_time = 0.0, previous_time = 0.0, first_step = 0.0, last_time = 0.0;
  int first_row_line = 0;
  std::size_t columns = 0;
  std::vector<double> row;
  for_each_line(lines, 0, reader, [&](int line_no, std::string_view line) {
    // '%' (MATLAB) and '#' start comments, also after data on a line.
    if (const auto c = line.find_first_of("%#"); c != std::string_view::npos)
      line = line.substr(0, c);
    const auto toks = tokens_of(line, ",;");
    if (toks.empty()) return true;
    if (columns == 0) {
      columns = toks.size();
      first_row_line = line_no;
    } else if (toks.size() != columns) {
      throw RecordError(path, line_no,
                        "row has " + std::to_string(toks.size()) + " columns but line " +
                            std::to_string(first_row_line) + " has " + std::to_string(columns));
    }
    row.clear();
    for (std::string_view tok : toks) row.push_back(number_or_throw(path, line_no, tok, hint));
    const auto need = [&](int index, const char* what) {
      if (static_cast<std::size_t>(index) >= columns)
        throw RecordError(path, line_no,
                          std::string(what) + " index " + std::to_string(index) +
                              " (0-based) is beyond this row's " + std::to_string(columns) +
                              " columns");
    };
    need(options.column, "column");
    if (has_time) need(options.time_column, "time column");
    if (accel.size() >= static_cast<std::size_t>(kMaxSamples))
      throw RecordError(path, line_no, "more than 1e8 samples: not a usable record");
    accel.push_back(row[static_cast<std::size_t>(options.column)] * factor);
    if (has_time) {
      const double t = row[static_cast<std::size_t>(options.time_column)];
      if (accel.size() == 1) {
        first_time = t;
      } else if (accel.size() == 2) {
        first_step = t - previous_time;
        if (!(first_step > 0.0))
          throw RecordError(
              path, line_no,
              "time does not increase (step " + fmt(first_step) + " s); dt must be > 0");
      } else {
        const double step = t - previous_time;
        if (!(std::abs(step - first_step) <= 1e-6 * first_step))
          throw RecordError(path, line_no,
                            "time step " + fmt(step) + " s differs from the first step " +
                                fmt(first_step) +
                                " s (samples must be uniform within 1e-6 relative)");
      }
      previous_time = last_time = t;
    }
    return true;
  });
  if (accel.empty()) throw RecordError(path, 0, "no data rows (only comments or blank lines)");

  double dt = 0.0;
  if (has_time) {
    if (accel.size() < 2)
      throw RecordError(path, first_row_line,
                        "need at least 2 rows to take dt from the time column");
    // dt is the mean step, which averages out rounding of the printed times.
    dt = (last_time - first_time) / static_cast<double>(accel.size() - 1);
    if (options.dt != 0.0 && !(std::abs(options.dt - dt) <= 1e-6 * dt))
      throw RecordError(path, 0,
                        "dt = " + fmt(options.dt) + " s was given but the time column has step " +
                            fmt(dt) + " s; give one or the other");
    // A first time other than 0 (e.g. a record cut from a longer one) is shifted to t = 0:
    // sample k is at k*dt from the start of the record, as everywhere in isopound.
  } else {
    if (options.dt == 0.0)
      throw RecordError(
          path, 0,
          "no time step: a column file without a time column needs dt > 0" + std::string(hint));
    if (!(options.dt > 0.0) || !std::isfinite(options.dt))
      throw RecordError(path, 0, "dt = " + fmt(options.dt) + " s: the time step must be > 0");
    dt = options.dt;
  }

  GroundMotion motion;
  motion.name = std::filesystem::path(path).stem().string();
  motion.dt = dt;
  accel.shrink_to_fit();
  motion.acceleration = std::move(accel);
  return motion;
}

bool has_at2_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".at2";
}

}  // namespace

RecordError::RecordError(const std::string& file, int line, const std::string& what)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " + what),
      file_(file),
      line_(line) {}

double GroundMotion::at(double t) const {
  if (acceleration.empty() || !(dt > 0.0)) return 0.0;
  if (!(t >= 0.0 && t <= duration())) return 0.0;  // also catches NaN
  const double x = t / dt;
  const std::size_t last = acceleration.size() - 1;
  const auto k = std::min(static_cast<std::size_t>(x), last);
  if (k == last) return acceleration[last];
  const double r = x - static_cast<double>(k);
  return acceleration[k] + r * (acceleration[k + 1] - acceleration[k]);
}

GroundMotionPeaks peaks_of(const GroundMotion& motion) {
  // Zero initial velocity and displacement and no baseline correction: the records are
  // already processed, and correcting here would hide what the structure actually feels.
  // Peaks are of the exact piecewise-quadratic velocity and piecewise-cubic displacement,
  // so extrema between samples (where a or v changes sign) are found too.
  GroundMotionPeaks pk;
  const auto& a = motion.acceleration;
  if (a.empty()) return pk;
  const double dt = motion.dt;
  auto track = [](double value, double t, double& peak, double& t_peak) {
    if (std::abs(value) > peak) {
      peak = std::abs(value);
      t_peak = t;
    }
  };
  track(a[0], 0.0, pk.pga, pk.t_pga);
  double v = 0.0, d = 0.0;
  for (std::size_t k = 0; k + 1 < a.size(); ++k) {
    const double a0 = a[k], a1 = a[k + 1];
    const double t0 = static_cast<double>(k) * dt;
    const double da = (a1 - a0) / dt;  // slope of the acceleration in the step
    // Velocity extremum inside the step where a(s) = a0 + da s = 0.
    if (a0 * a1 < 0.0) {
      const double s = a0 * dt / (a0 - a1);
      track(v + 0.5 * a0 * s, t0 + s, pk.pgv, pk.t_pgv);
    }
    // Displacement extrema inside the step where v(s) = v + a0 s + da s^2/2 = 0
    // (numerically stable quadratic roots; a root of 0 or dt is a sample, handled below).
    {
      const double c2 = 0.5 * da, c1 = a0, c0 = v;
      const double disc = c1 * c1 - 4.0 * c2 * c0;
      if (disc >= 0.0) {
        const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
        double roots[2] = {-1.0, -1.0};
        if (c2 != 0.0) roots[0] = q / c2;
        if (q != 0.0) roots[1] = c0 / q;
        for (double s : roots) {
          if (std::isfinite(s) && s > 0.0 && s < dt)
            track(d + v * s + 0.5 * a0 * s * s + da * s * s * s / 6.0, t0 + s, pk.pgd, pk.t_pgd);
        }
      }
    }
    const double d1 = d + dt * v + dt * dt * (2.0 * a0 + a1) / 6.0;
    v += dt * (a0 + a1) / 2.0;
    d = d1;
    const double t1 = static_cast<double>(k + 1) * dt;
    track(a1, t1, pk.pga, pk.t_pga);
    track(v, t1, pk.pgv, pk.t_pgv);
    track(d, t1, pk.pgd, pk.t_pgd);
  }
  return pk;
}

std::optional<RecordReadOptions::Format> sniff_record_format(const std::string& path) {
  try {
    LineReader reader(path);
    const std::vector<std::string> head = read_head(reader, kAutoHeaderLines);
    if (find_peer_header(head, kAutoHeaderLines) || has_at2_extension(path))
      return RecordReadOptions::Format::kPeer;
    return RecordReadOptions::Format::kColumns;
  } catch (const RecordError&) {
    // Reported when the record is read; the extension still says what it is meant to be.
    if (has_at2_extension(path)) return RecordReadOptions::Format::kPeer;
    return std::nullopt;
  }
}

GroundMotion read_record(const std::string& path, const RecordReadOptions& options) {
  if (!std::isfinite(options.scale))
    throw RecordError(path, 0, "scale factor " + fmt(options.scale) + " is not finite");
  LineReader reader(path);
  using Format = RecordReadOptions::Format;
  const std::size_t head_lines =
      options.format == Format::kPeer ? kMaxPeerHeaderLines : kAutoHeaderLines;
  const std::vector<std::string> lines = read_head(reader, head_lines);
  if (std::all_of(lines.begin(), lines.end(), [](const std::string& l) { return is_blank(l); }) &&
      lines.size() < head_lines)
    throw RecordError(path, 0, "empty file (no header and no data)");

  // PEER files state their unit (header line 3, read by read_peer) and carry their own DT, so
  // options.unit and options.dt do not apply to them.
  const double peer_factor = options.scale;
  switch (options.format) {
    case Format::kPeer: {
      const auto header = find_peer_header(lines, lines.size());
      if (!header) throw_missing_header(path, lines, lines.size());
      return read_peer(path, lines, reader, *header, peer_factor);
    }
    case Format::kColumns:
      return read_columns(path, lines, reader, options, {});
    case Format::kAuto:
      break;
  }
  if (const auto header = find_peer_header(lines, kAutoHeaderLines))
    return read_peer(path, lines, reader, *header, peer_factor);
  // An .AT2 file without an NPTS/DT line is a broken PEER file, not a column file.
  if (has_at2_extension(path)) throw_missing_header(path, lines, kAutoHeaderLines);
  return read_columns(
      path, lines, reader, options,
      "; read as a plain column file because no NPTS/DT line was found in the first " +
          std::to_string(kAutoHeaderLines) + " lines");
}

namespace {

void check_pulse_shape(const PulseParameters& p) {
  if (!(p.period > 0.0) || !std::isfinite(p.period))
    throw std::invalid_argument("pulse period must be > 0 s (got " + fmt(p.period) + ")");
  if (!(p.gamma > 1.0) || !std::isfinite(p.gamma))
    throw std::invalid_argument("pulse gamma must be > 1 (got " + fmt(p.gamma) + ")");
  if (!std::isfinite(p.amplitude) || !std::isfinite(p.phase) || !std::isfinite(p.t_peak))
    throw std::invalid_argument("pulse amplitude, phase and t_peak must be finite");
}

}  // namespace

double pulse_velocity(const PulseParameters& p, double t) {
  check_pulse_shape(p);
  const double tau = t - p.t_peak;
  if (std::abs(tau) > 0.5 * p.gamma * p.period) return 0.0;
  const double w = 2.0 * std::numbers::pi / p.period;
  return 0.5 * p.amplitude * (1.0 + std::cos(w * tau / p.gamma)) * std::cos(w * tau + p.phase);
}

double pulse_acceleration(const PulseParameters& p, double t) {
  check_pulse_shape(p);
  const double tau = t - p.t_peak;
  if (std::abs(tau) > 0.5 * p.gamma * p.period) return 0.0;
  const double w = 2.0 * std::numbers::pi / p.period;
  const double we = w / p.gamma;  // envelope frequency
  // d/dt of A/2 E(tau) C(tau): envelope term E' C plus carrier term E C'. Both vanish at the
  // window edges (E = E' = 0 there), so the acceleration is continuous.
  const double envelope = 1.0 + std::cos(we * tau);
  const double d_envelope = -we * std::sin(we * tau);
  const double carrier = std::cos(w * tau + p.phase);
  const double d_carrier = -w * std::sin(w * tau + p.phase);
  return 0.5 * p.amplitude * (d_envelope * carrier + envelope * d_carrier);
}

GroundMotion make_pulse(const PulseParameters& p) {
  check_pulse_shape(p);
  if (!(p.dt > 0.0) || !std::isfinite(p.dt))
    throw std::invalid_argument("pulse dt must be > 0 s (got " + fmt(p.dt) + ")");
  if (!(p.duration > 0.0) || !std::isfinite(p.duration))
    throw std::invalid_argument("pulse duration must be > 0 s (got " + fmt(p.duration) + ")");
  const double steps = std::round(p.duration / p.dt);
  if (steps < 1.0)
    throw std::invalid_argument("pulse duration " + fmt(p.duration) +
                                " s is shorter than one dt (" + fmt(p.dt) + " s)");
  if (steps > static_cast<double>(kMaxSamples))
    throw std::invalid_argument("pulse duration / dt = " + fmt(steps) + " samples is too many");
  const auto n = static_cast<std::size_t>(steps);
  GroundMotion motion;
  motion.name = "pulse";
  motion.dt = p.dt;
  motion.acceleration.resize(n + 1);
  for (std::size_t k = 0; k <= n; ++k)
    motion.acceleration[k] = pulse_acceleration(p, static_cast<double>(k) * p.dt);
  return motion;
}

}  // namespace isopound
