// Tests of solver/ground_motion: the real records in ../shared/records, PEER header variants,
// column files, file:line errors, exact peak integration, and the near-fault pulse.
#include "solver/excitation/ground_motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <ostream>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "tests/test_support.h"

namespace isopound {
namespace {

namespace fs = std::filesystem;
constexpr double kG = 9.81;

// ---------------------------------------------------------------------------------------------
// Real records (README table, section 1)

struct RecordCase {
  const char* file;
  int column;  // -1: PEER file; >= 0: erzikan.txt column
  std::size_t npts;
  double dt;     // s
  double pga_g;  // as printed in the README (3 digits)
  double t_pga;  // s, < 0 when the README does not give it
  int sign;      // sign of the peak sample (0: not given)
};

const RecordCase kRecords[] = {
    {"RSN1084_NORTHR_SCS052.AT2", -1, 8773, 0.005, 0.623, 4.71, +1},
    {"RSN1084_NORTHR_SCS142.AT2", -1, 8773, 0.005, 0.923, 7.00, -1},
    {"SCS052.AT2", -1, 8000, 0.005, 0.613, -1.0, 0},
    {"SCS142.AT2", -1, 8000, 0.005, 0.897, -1.0, 0},
    {"RSN828_CAPEMEND_PET000.AT2", -1, 1800, 0.02, 0.591, 3.42, -1},
    {"erzikan.txt", 0, 4260, 0.005, 0.515, -1.0, 0},
    {"erzikan.txt", 1, 4260, 0.005, 0.496, -1.0, 0},
    {"RSN1605_DUZCE_DZC270.AT2", -1, 5177, 0.005, 0.515, -1.0, 0},
    {"CPM000.AT2", -1, 1500, 0.02, 1.497, -1.0, 0},
    {"RSN6_IMPVALL.I_I-ELC180.AT2", -1, 5372, 0.01, 0.281, -1.0, 0},
    {"IELC180.AT2", -1, 4000, 0.01, 0.313, -1.0, 0},
    {"elCentro.AT2", -1, 1559, 0.02, 0.319, -1.0, 0},
    {"el_centro.AT2", -1, 1559, 0.02, 0.319, -1.0, 0},
    {"Oak_2_50_5_FN.AT2", -1, 7997, 0.005, 0.910, -1.0, 0},
};

// Readable test listings instead of a byte dump of the struct.
void PrintTo(const RecordCase& c, std::ostream* os) {
  *os << c.file;
  if (c.column >= 0) *os << " column " << c.column;
}

RecordReadOptions options_for(const RecordCase& c) {
  RecordReadOptions opt;
  if (c.column >= 0) {  // erzikan.txt: 2 columns, no time column, cm/s^2, dt only in a comment
    opt.column = c.column;
    opt.dt = 0.005;
    opt.unit = AccelerationUnit::kCentimetrePerSecond2;
  }
  return opt;
}

class GroundMotionRecord : public ::testing::TestWithParam<RecordCase> {};

TEST_P(GroundMotionRecord, ReadsNptsDtAndPga) {
  ISOPOUND_REQUIRE_RECORDS();
  const RecordCase& c = GetParam();
  const std::string path = (test::records_dir() / c.file).string();
  const GroundMotion m = read_record(path, options_for(c));
  EXPECT_EQ(m.acceleration.size(), c.npts);
  EXPECT_DOUBLE_EQ(m.dt, c.dt);
  EXPECT_EQ(m.name, fs::path(c.file).stem().string());
  const GroundMotionPeaks pk = peaks_of(m);
  // README prints PGA in g to 3 digits: rounding leaves at most 0.0005 g.
  EXPECT_NEAR(pk.pga / kG, c.pga_g, 0.0006);
  if (c.t_pga >= 0.0) {
    EXPECT_NEAR(pk.t_pga, c.t_pga, 0.005 + 1e-9);  // printed to 0.01 s
    const auto k = static_cast<std::size_t>(std::llround(pk.t_pga / m.dt));
    ASSERT_LT(k, m.acceleration.size());
    EXPECT_EQ(m.acceleration[k] > 0.0 ? 1 : -1, c.sign);
  }
  // Processed records: the velocity and displacement stay physical (no integration blow-up).
  EXPECT_GT(pk.pgv, 0.0);
  EXPECT_LT(pk.pgv, 5.0);
  EXPECT_LT(pk.pgd, 10.0);
}

std::string case_name(const ::testing::TestParamInfo<RecordCase>& info) {
  std::string name = info.param.file;
  if (info.param.column >= 0) name += "_col" + std::to_string(info.param.column);
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(GroundMotionFiles, GroundMotionRecord, ::testing::ValuesIn(kRecords),
                         case_name);

// Every record file in the folder is in the table above (nothing silently untested).
TEST(GroundMotionRecords, EveryFileInFolderIsCovered) {
  ISOPOUND_REQUIRE_RECORDS();
  std::set<std::string> known;
  for (const RecordCase& c : kRecords) known.insert(c.file);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(test::records_dir())) {
    const std::string name = entry.path().filename().string();
    if (name == "README.md") continue;
    ++files;
    EXPECT_TRUE(known.count(name)) << name << " is in ../shared/records but not tested";
  }
  EXPECT_EQ(files, static_cast<int>(known.size()));
}

// The two El Centro copies differ only in their headers and trailers.
TEST(GroundMotionRecords, ElCentroCopiesAgree) {
  ISOPOUND_REQUIRE_RECORDS();
  const GroundMotion a = read_record((test::records_dir() / "elCentro.AT2").string());
  const GroundMotion b = read_record((test::records_dir() / "el_centro.AT2").string());
  EXPECT_EQ(a.acceleration, b.acceleration);
  EXPECT_DOUBLE_EQ(a.acceleration.front(), 0.00630 * kG);
  EXPECT_DOUBLE_EQ(a.acceleration.back(), 0.0);
}

TEST(GroundMotionRecords, FirstAndLastValuesOfNgaWest2File) {
  ISOPOUND_REQUIRE_RECORDS();
  const GroundMotion m = read_record((test::records_dir() / "RSN1084_NORTHR_SCS052.AT2").string());
  EXPECT_DOUBLE_EQ(m.acceleration.front(), -.4981725E-02 * kG);
  EXPECT_DOUBLE_EQ(m.acceleration.back(), .1139843E-02 * kG);
}

TEST(GroundMotionRecords, ScaleMultipliesPeerValues) {
  ISOPOUND_REQUIRE_RECORDS();
  RecordReadOptions opt;
  opt.scale = 1.5;
  const std::string path = (test::records_dir() / "CPM000.AT2").string();
  const GroundMotion scaled = read_record(path, opt);
  const GroundMotion plain = read_record(path);
  ASSERT_EQ(scaled.acceleration.size(), plain.acceleration.size());
  for (std::size_t k = 0; k < plain.acceleration.size(); k += 97)
    EXPECT_DOUBLE_EQ(scaled.acceleration[k], 1.5 * plain.acceleration[k]);
}

// ---------------------------------------------------------------------------------------------
// Synthetic files in a private temporary directory

class GroundMotionTempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("isopound_gm_" + std::string(info->name()) + "_" +
                                        std::to_string(rd()) + std::to_string(rd()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  // Writes bytes exactly as given (binary: CRLF and a missing final newline are kept).
  std::string write(const std::string& name, const std::string& content) const {
    const fs::path path = dir_ / name;
    std::ofstream out(path, std::ios::binary);
    out << content;
    return path.string();
  }
  fs::path dir_;
};

// Twelve values in NGA-West2 layout (5 per row, no leading zero, short last row).
const char* const kNgaData =
    "  -.4981725E-02  -.4964618E-02   .1000000E+00  -.2500000E-01   .3000000E-02\n"
    "   .1234567E+01  -.9999999E+00   .5000000E-03   .0000000E+00  -.7500000E-01\n"
    "   .2000000E-01  -.1000000E-01\n";
const std::vector<double> kNgaValuesG = {-.4981725E-02, -.4964618E-02, 0.1, -0.025, 0.003, 1.234567,
                                         -0.9999999,    0.0005,        0.0, -0.075, 0.02,  -0.01};

std::string to_crlf(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == '\n') out += '\r';
    out += ch;
  }
  return out;
}

void expect_values_g(const GroundMotion& m, const std::vector<double>& g, double dt) {
  EXPECT_DOUBLE_EQ(m.dt, dt);
  ASSERT_EQ(m.acceleration.size(), g.size());
  for (std::size_t k = 0; k < g.size(); ++k)
    EXPECT_DOUBLE_EQ(m.acceleration[k], g[k] * kG) << "k=" << k;
}

class GroundMotionHeader : public GroundMotionTempDir {};

TEST_F(GroundMotionHeader, NgaWest2WithFilterInfo) {
  const auto path =
      write("nga.AT2", std::string("PEER NGA STRONG MOTION DATABASE RECORD\n"
                                   "Northridge-01, 1/17/1994, Sylmar - Converter Sta, 52\n"
                                   "ACCELERATION TIME SERIES IN UNITS OF G\n"
                                   "NPTS=     12, DT=   .0050 SEC,   4 POLE @    40.00000 HZ,  "
                                   "-5 POLE @      .20000\n") +
                           kNgaData);
  const GroundMotion m = read_record(path);
  EXPECT_EQ(m.name, "nga");
  expect_values_g(m, kNgaValuesG, 0.005);
}

TEST_F(GroundMotionHeader, NgaWest2TrailingCommaAndBlanks) {
  const auto path =
      write("rsn6.AT2", std::string("PEER NGA STRONG MOTION DATABASE RECORD\n"
                                    "Imperial Valley-02, 5/19/1940, El Centro Array #9, 180\n"
                                    "ACCELERATION TIME SERIES IN UNITS OF G\n"
                                    "NPTS=     12, DT=   .0100 SEC,                        \n") +
                            kNgaData);
  expect_values_g(read_record(path), kNgaValuesG, 0.01);
}

TEST_F(GroundMotionHeader, NgaWest2NoCommaCrlf) {
  const auto path =
      write("rsn828.AT2", to_crlf(std::string("PEER NGA STRONG MOTION DATABASE RECORD\n"
                                              "Cape Mendocino, 4/25/1992, Petrolia, 0\n"
                                              "ACCELERATION TIME SERIES IN UNITS OF G\n"
                                              "NPTS=     12, DT=   .0200 SEC           \n") +
                                  kNgaData));
  expect_values_g(read_record(path), kNgaValuesG, 0.02);
}

TEST_F(GroundMotionHeader, OlderPeerProcessingBy) {
  const auto path =
      write("scs.AT2", std::string("PEER STRONG MOTION DATABASE RECORD. PROCESSING BY DWP.\n"
                                   "NORTHRIDGE, 1/17/94 12:31, SYLMAR-CONVERTER STA, 052 (DWP "
                                   "STATION 74)\n"
                                   "ACCELERATION TIME HISTORY IN UNITS OF G. FILTER POINTS: "
                                   "HP=unknown LP=unknown\n"
                                   "NPTS=  12, DT= .00500 SEC\n") +
                           kNgaData);
  expect_values_g(read_record(path), kNgaValuesG, 0.005);
}

TEST_F(GroundMotionHeader, LowerCaseDtWithoutSec) {
  const auto path =
      write("anla.AT2", std::string("PEER STRONG MOTION DATABASE RECORD. PROCESSING BY X.\n"
                                    "SOME EVENT\n"
                                    "ACCELERATION TIME HISTORY IN UNITS OF G\n"
                                    "NPTS=   12, dt=  .02000\n") +
                            kNgaData);
  expect_values_g(read_record(path), kNgaValuesG, 0.02);
}

TEST_F(GroundMotionHeader, LowerCaseDtWithSec) {
  const auto path =
      write("pbfeas.AT2", std::string("PEER STRONG MOTION DATABASE RECORD. PROCESSING BY X.\n"
                                      "SOME EVENT\n"
                                      "ACCELERATION TIME HISTORY IN UNITS OF G\n"
                                      "NPTS=   12, dt=   .0100 SEC\n") +
                              kNgaData);
  expect_values_g(read_record(path), kNgaValuesG, 0.01);
}

TEST_F(GroundMotionHeader, ValuesFirstOnLine7AfterSixLineHeaderCrlf) {
  const auto path =
      write("oak.AT2", to_crlf("Orig PEER filename = IMPVALL/H-EMO_233_FN.acc, Scale factor = "
                               "2.4072 \n"
                               "  H1 for rotation: IMPERIAL VALLEY 10/15/79 2316, 000    \n"
                               "  H2 for rotation: IMPERIAL VALLEY 10/15/79 2316, 270    \n"
                               "  rotation angle - clockwise   -37.0\n"
                               "  FN component, azimuth =   233.0\n"
                               "  Acceleration in g\n"
                               "7 0.0050 NPTS, DT \n"
                               "0.008941     0.009683     -0.009749     0.009750     0.009759 \n"
                               "0.009777     -0.000001 "));  // short last row, no newline
  expect_values_g(read_record(path),
                  {0.008941, 0.009683, -0.009749, 0.009750, 0.009759, 0.009777, -0.000001}, 0.005);
}

TEST_F(GroundMotionHeader, ValuesFirstAfterFourLineHeader) {
  const auto path =
      write("pul164.AT2", std::string("PEER STRONG MOTION DATABASE RECORD. PROCESSING BY X.\n"
                                      "SAN FERNANDO 02/09/71 14:00, PACOIMA DAM, 164\n"
                                      "ACCELERATION TIME HISTORY IN UNITS OF G\n"
                                      "12    0.0100    NPTS, DT\n") +
                              kNgaData);
  expect_values_g(read_record(path), kNgaValuesG, 0.01);
}

TEST_F(GroundMotionHeader, FreeTextHeaderEightPerRowNoFinalNewline) {
  // Line 2 starts with a number but is not data: only the NPTS/DT line ends the header.
  const auto path =
      write("elc.AT2",
            "Data for El Centro 1940 North South Component (Peknold Version)\n"
            "10 points at equal spacing of 0.02 sec Points are listed in the format of 8F10.5\n"
            "The units are (g)\n"
            "NPTS=  10, DT= .02000 SEC\n"
            "   0.00630   0.00364   0.00099   0.00428   0.00758   0.01087   0.00682   0.00277\n"
            "  -0.00128   0.00000");
  expect_values_g(
      read_record(path),
      {0.00630, 0.00364, 0.00099, 0.00428, 0.00758, 0.01087, 0.00682, 0.00277, -0.00128, 0.0},
      0.02);
}

TEST_F(GroundMotionHeader, BeginDataMarkerEndTrailerAndBlankLines) {
  const auto path =
      write("el_c.AT2",
            "Data for El Centro 1940 North South Component (Peknold Version)\n"
            "10 points at equal spacing of 0.02 sec\n"
            "Points are listed in the format of 8F10.5, i.e., 8 points across in\n"
            "a row with 5 decimal places\n"
            "The units are (g)\n"
            "*** Begin data ***\n"
            "NPTS=  10, DT= .02000 SEC\n"
            "   0.00630   0.00364   0.00099   0.00428   0.00758   0.01087   0.00682   0.00277\n"
            "  -0.00128   0.00000\n"
            "*** End Data ***\n"
            "\n"
            "\n");
  expect_values_g(
      read_record(path),
      {0.00630, 0.00364, 0.00099, 0.00428, 0.00758, 0.01087, 0.00682, 0.00277, -0.00128, 0.0},
      0.02);
}

TEST_F(GroundMotionHeader, ExplicitPeerFormatOnAnyExtension) {
  const auto path =
      write("record.acc", std::string("header\nheader\nheader\nNPTS= 12, DT= .005\n") + kNgaData);
  RecordReadOptions opt;
  opt.format = RecordReadOptions::Format::kPeer;
  expect_values_g(read_record(path, opt), kNgaValuesG, 0.005);
  expect_values_g(read_record(path), kNgaValuesG, 0.005);  // kAuto finds the header too
}

TEST_F(GroundMotionHeader, SpacedHeaderAndHugeLinesDoNotConfuseTheMatcher) {
  // Spaces around '=' and ','; a 1 MB free-text line (the matcher must not recurse per char).
  const std::string long_line = "NPTS=" + std::string(1'000'000, ' ') + "x\n";
  const auto path = write(
      "spaced.AT2", "PEER\n" + long_line + "ACCELERATION\nNpts = 12 , Dt = 5e-3 sec\n" + kNgaData);
  expect_values_g(read_record(path), kNgaValuesG, 0.005);
}

class GroundMotionColumns : public GroundMotionTempDir {};

TEST_F(GroundMotionColumns, PercentCommentsTwoColumnsCrlfCmPerS2) {
  const auto path = write("erz.txt", to_crlf("%ERZIKAN-like. First column N-S, second E-W.\n"
                                             "%Acc. in cm/sec^2 and dt=0.005 sec.\n"
                                             "  2.9638835e-001  1.4237498e-001\n"
                                             " -5.7086950e+000 -5.7086950e+000\n"
                                             "  1.0000000e+002  -2.0000000e+002\n"));
  RecordReadOptions opt;
  opt.dt = 0.005;
  opt.unit = AccelerationUnit::kCentimetrePerSecond2;
  opt.column = 1;
  const GroundMotion ew = read_record(path, opt);
  EXPECT_EQ(ew.name, "erz");
  EXPECT_DOUBLE_EQ(ew.dt, 0.005);
  ASSERT_EQ(ew.acceleration.size(), 3u);
  EXPECT_DOUBLE_EQ(ew.acceleration[0], 0.01 * 1.4237498e-001);
  EXPECT_DOUBLE_EQ(ew.acceleration[2], -2.0);
  opt.column = 0;
  EXPECT_DOUBLE_EQ(read_record(path, opt).acceleration[2], 1.0);
}

TEST_F(GroundMotionColumns, HashCommentsUnitsAndScale) {
  const auto path = write("a.dat", "# single column in g\n0.1\n-0.2   # trailing comment\n\n0.3\n");
  RecordReadOptions opt;
  opt.dt = 0.01;
  opt.scale = 2.0;
  const GroundMotion g = read_record(path, opt);
  ASSERT_EQ(g.acceleration.size(), 3u);
  EXPECT_DOUBLE_EQ(g.acceleration[1], -0.2 * kG * 2.0);
  opt.unit = AccelerationUnit::kMetrePerSecond2;
  EXPECT_DOUBLE_EQ(read_record(path, opt).acceleration[2], 0.6);
}

TEST_F(GroundMotionColumns, TimeColumnGivesDtAndIsShiftedToZero) {
  const auto path = write("t.csv", "# t, a\n10.00, 1.0\n10.02, 2.0\n10.04, 3.0\n10.06, 4.0\n");
  RecordReadOptions opt;
  opt.time_column = 0;
  opt.column = 1;
  opt.unit = AccelerationUnit::kMetrePerSecond2;
  const GroundMotion m = read_record(path, opt);
  EXPECT_NEAR(m.dt, 0.02, 1e-15);
  ASSERT_EQ(m.acceleration.size(), 4u);
  EXPECT_DOUBLE_EQ(m.at(0.0), 1.0);  // first sample at t = 0 after the shift
  EXPECT_DOUBLE_EQ(m.acceleration[3], 4.0);
}

TEST_F(GroundMotionColumns, ExplicitColumnsFormatIgnoresNptsText) {
  const auto path = write("c.AT2", "% NPTS= 3, DT= .01 is only a comment here\n1\n2\n3\n");
  RecordReadOptions opt;
  opt.format = RecordReadOptions::Format::kColumns;
  opt.dt = 0.1;
  opt.unit = AccelerationUnit::kMetrePerSecond2;
  const GroundMotion m = read_record(path, opt);
  EXPECT_DOUBLE_EQ(m.dt, 0.1);
  EXPECT_EQ(m.acceleration, (std::vector<double>{1.0, 2.0, 3.0}));
}

// ---------------------------------------------------------------------------------------------
// Errors: RecordError with the right line, and what() = "file:line: message"

class GroundMotionErrors : public GroundMotionTempDir {
 protected:
  void expect_error(const std::string& path, const RecordReadOptions& opt, int line,
                    const std::string& fragment) {
    try {
      const GroundMotion m = read_record(path, opt);
      ADD_FAILURE() << "no RecordError; read " << m.acceleration.size() << " values";
    } catch (const RecordError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.file(), path);
      EXPECT_EQ(e.line(), line) << what;
      EXPECT_NE(what.find(path + ":" + std::to_string(line) + ": "), std::string::npos) << what;
      EXPECT_NE(what.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << what;
    }
  }
  static std::string peer(const std::string& npts_line, const std::string& data) {
    return "PEER NGA STRONG MOTION DATABASE RECORD\nEvent, 1/1/2000, Station, 0\n"
           "ACCELERATION TIME SERIES IN UNITS OF G\n" +
           npts_line + "\n" + data;
  }
};

TEST_F(GroundMotionErrors, MissingFile) {
  expect_error((dir_ / "nope.AT2").string(), {}, 0, "cannot open");
}

TEST_F(GroundMotionErrors, EmptyFile) {
  expect_error(write("empty.AT2", ""), {}, 0, "empty file");
  expect_error(write("blank.txt", "\n   \r\n\n"), {}, 0, "empty file");
}

TEST_F(GroundMotionErrors, TruncatedPeer) {
  // 10 values on lines 5-6, NPTS says 12: the message gives both counts at the last line.
  const auto path = write("trunc.AT2", peer("NPTS=     12, DT=   .0050 SEC",
                                            "   .1E-01   .2E-01   .3E-01   .4E-01   .5E-01\n"
                                            "   .6E-01   .7E-01   .8E-01   .9E-01   .1E+00\n"));
  expect_error(path, {}, 6, "truncated record: found 10 values but NPTS = 12");
}

TEST_F(GroundMotionErrors, NonNumericToken) {
  const auto path = write("text.AT2", peer("NPTS=     10, DT=   .0050 SEC",
                                           "   .1E-01   .2E-01   .3E-01   .4E-01   .5E-01\n"
                                           "   .6E-01   abc   .8E-01   .9E-01   .1E+00\n"));
  expect_error(path, {}, 6, "non-numeric value 'abc' (expected a number)");
}

TEST_F(GroundMotionErrors, GluedFortranFieldsAreNotHalfRead) {
  const auto path =
      write("glued.AT2", peer("NPTS=  3, DT= .02000 SEC", "  -0.00128-0.00368   0.1\n"));
  expect_error(path, {}, 5, "non-numeric value '-0.00128-0.00368'");
}

TEST_F(GroundMotionErrors, MoreValuesThanNpts) {
  // NPTS = 8: value 9 is the 4th value on line 6.
  const auto path = write("extra.AT2", peer("NPTS=      8, DT=   .0050 SEC",
                                            "   .1E-01   .2E-01   .3E-01   .4E-01   .5E-01\n"
                                            "   .6E-01   .7E-01   .8E-01   .9E-01   .1E+00\n"));
  expect_error(path, {}, 6, "more values than NPTS = 8");
}

TEST_F(GroundMotionErrors, NanAndInfinity) {
  const auto path =
      write("nan.AT2", peer("NPTS=  4, DT= .01 SEC", "  .1E-01  NaN  .2E-01  .3E-01\n"));
  expect_error(path, {}, 5, "'NaN' is not finite");
  RecordReadOptions opt;
  opt.dt = 0.01;
  expect_error(write("inf.txt", "% c\n1.0 2.0\n3.0 -inf\n"), opt, 3, "'-inf' is not finite");
}

TEST_F(GroundMotionErrors, MissingNptsLineInAt2) {
  const auto path =
      write("nohdr.AT2", peer("ACCELERATION, SOME MORE TEXT", "   .1E-01   .2E-01\n"));
  expect_error(path, {}, 5, "no NPTS/DT header line");
  RecordReadOptions opt;
  opt.format = RecordReadOptions::Format::kPeer;
  expect_error(write("nohdr.txt", "text\n1 2 3\n"), opt, 2, "no NPTS/DT header line");
  expect_error(write("nodata.AT2", "just\ntext\n"), {}, 0, "no NPTS/DT header line");
}

TEST_F(GroundMotionErrors, UnreadableNptsLine) {
  const auto path = write("badhdr.AT2", peer("NPTS=     12", "   .1E-01   .2E-01\n"));
  expect_error(path, {}, 4, "cannot read NPTS and DT");
}

TEST_F(GroundMotionErrors, NonPositiveDt) {
  expect_error(write("dt0.AT2", peer("NPTS=  2, DT= .0000 SEC", "  .1 .2\n")), {}, 4,
               "must be > 0");
  expect_error(write("npts0.AT2", peer("NPTS=  0, DT= .0100 SEC", "\n")), {}, 4, "NPTS = 0");
  RecordReadOptions opt;
  opt.dt = -0.01;
  expect_error(write("neg.txt", "1\n2\n"), opt, 0, "must be > 0");
}

TEST_F(GroundMotionErrors, MissingDtForColumns) {
  expect_error(write("nodt.txt", "% no dt\n1.0\n2.0\n"), {}, 0, "needs dt > 0");
}

TEST_F(GroundMotionErrors, ColumnIndexBeyondRow) {
  RecordReadOptions opt;
  opt.dt = 0.005;
  opt.column = 2;
  expect_error(write("two.txt", "%a\n%b\n 1.0 2.0\n 3.0 4.0\n"), opt, 3,
               "column index 2 (0-based) is beyond this row's 2 columns");
}

TEST_F(GroundMotionErrors, InconsistentColumnCounts) {
  RecordReadOptions opt;
  opt.dt = 0.005;
  expect_error(write("ragged.txt", "1.0 2.0\n3.0 4.0\n5.0\n"), opt, 3,
               "row has 1 columns but line 1 has 2");
}

TEST_F(GroundMotionErrors, NonUniformTimeColumn) {
  RecordReadOptions opt;
  opt.time_column = 0;
  opt.column = 1;
  expect_error(write("t.txt", "0.00 1\n0.01 2\n0.03 3\n0.04 4\n"), opt, 3,
               "differs from the first step");
  expect_error(write("back.txt", "0.00 1\n0.01 2\n0.00 3\n"), opt, 3,
               "differs from the first step");
  expect_error(write("flat.txt", "0.00 1\n0.00 2\n"), opt, 2, "dt must be > 0");
}

TEST_F(GroundMotionErrors, TextHeaderInColumnFileSaysWhyColumns) {
  RecordReadOptions opt;
  opt.dt = 0.01;
  expect_error(write("hdr.txt", "time accel\n0 1\n"), opt, 1,
               "non-numeric value 'time' (expected a number); read as a plain column file");
}

TEST_F(GroundMotionErrors, VelocityFileIsRefused) {
  const auto path = write("vel.VT2",
                          "PEER NGA STRONG MOTION DATABASE RECORD\nEvent\n"
                          "VELOCITY TIME SERIES IN UNITS OF CM/S\nNPTS=  2, DT= .01 SEC\n 1 2\n");
  expect_error(path, {}, 3, "velocity or displacement");
}

// ---------------------------------------------------------------------------------------------
// Interpolation and peaks

TEST(GroundMotionAt, LinearInsideZeroOutside) {
  GroundMotion m;
  m.dt = 0.5;
  m.acceleration = {1.0, 3.0, -1.0};
  EXPECT_DOUBLE_EQ(m.duration(), 1.0);
  EXPECT_DOUBLE_EQ(m.at(0.0), 1.0);
  EXPECT_DOUBLE_EQ(m.at(0.25), 2.0);
  EXPECT_DOUBLE_EQ(m.at(0.5), 3.0);
  EXPECT_DOUBLE_EQ(m.at(0.875), 0.0);
  EXPECT_DOUBLE_EQ(m.at(1.0), -1.0);
  EXPECT_EQ(m.at(-1e-9), 0.0);
  EXPECT_EQ(m.at(1.0 + 1e-9), 0.0);
  EXPECT_EQ(m.at(std::nan("")), 0.0);
}

TEST(GroundMotionPeaks, ConstantAccelerationIsIntegratedExactly) {
  const double a0 = 2.5, dt = 0.01;
  const std::size_t steps = 1000;
  GroundMotion m;
  m.dt = dt;
  m.acceleration.assign(steps + 1, a0);
  const double T = m.duration();
  const GroundMotionPeaks pk = peaks_of(m);
  EXPECT_DOUBLE_EQ(pk.pga, a0);
  EXPECT_NEAR(pk.pgv, a0 * T, 1e-12 * a0 * T);
  EXPECT_NEAR(pk.pgd, a0 * T * T / 2.0, 1e-12 * a0 * T * T / 2.0);
  EXPECT_DOUBLE_EQ(pk.t_pgv, T);
  EXPECT_DOUBLE_EQ(pk.t_pgd, T);
}

TEST(GroundMotionPeaks, LinearRampMatchesClosedForm) {
  // a = c t: v = c t^2/2, d = c t^3/6, exact for piecewise-linear integration.
  const double c = -0.7, dt = 0.02;
  GroundMotion m;
  m.dt = dt;
  for (int k = 0; k <= 500; ++k) m.acceleration.push_back(c * k * dt);
  const double T = m.duration();
  const GroundMotionPeaks pk = peaks_of(m);
  EXPECT_NEAR(pk.pga, std::abs(c) * T, 1e-12);
  EXPECT_NEAR(pk.pgv, std::abs(c) * T * T / 2.0, 1e-12 * std::abs(c) * T * T);
  EXPECT_NEAR(pk.pgd, std::abs(c) * T * T * T / 6.0, 1e-12 * std::abs(c) * T * T * T);
}

TEST(GroundMotionPeaks, VelocityPeakBetweenSamplesIsFound) {
  // a = 1 - 2t on one step of 1 s: v = t - t^2 peaks at t = 0.5 (0.25) although v(1) = 0;
  // d = t^2/2 - t^3/3 keeps rising to 1/6 at t = 1.
  GroundMotion m;
  m.dt = 1.0;
  m.acceleration = {1.0, -1.0};
  GroundMotionPeaks pk = peaks_of(m);
  EXPECT_DOUBLE_EQ(pk.pgv, 0.25);
  EXPECT_DOUBLE_EQ(pk.t_pgv, 0.5);
  EXPECT_NEAR(pk.pgd, 1.0 / 6.0, 1e-15);
  EXPECT_DOUBLE_EQ(pk.t_pgd, 1.0);
  // Zero record: all peaks zero.
  m.acceleration = {0.0, 0.0};
  pk = peaks_of(m);
  EXPECT_EQ(pk.pga, 0.0);
  EXPECT_EQ(pk.pgv, 0.0);
  EXPECT_EQ(pk.pgd, 0.0);
}

TEST(GroundMotionPeaks, DisplacementPeakInsideStep) {
  // Two steps of 1 s: a = 1, 1, -3. After step 1: v = 1, d = 0.5. Step 2: v = 1 + s - 2 s^2,
  // zero at s = 1 (the end), so pick a = 1, 1, -5: v = 1 + s - 3 s^2 = 0 at s = (1+sqrt(13))/6.
  GroundMotion m;
  m.dt = 1.0;
  m.acceleration = {1.0, 1.0, -5.0};
  const GroundMotionPeaks pk = peaks_of(m);
  const double s = (1.0 + std::sqrt(13.0)) / 6.0;
  const double d = 0.5 + s + 0.5 * s * s - s * s * s;  // d0 + v0 s + a0 s^2/2 + da s^3/6, da = -6
  EXPECT_NEAR(pk.pgd, d, 1e-14);
  EXPECT_NEAR(pk.t_pgd, 1.0 + s, 1e-14);
}

// ---------------------------------------------------------------------------------------------
// Near-fault pulse

PulseParameters test_pulse() {
  PulseParameters p;
  p.amplitude = 0.8;
  p.period = 1.5;
  p.gamma = 2.5;
  p.phase = std::numbers::pi / 3.0;
  p.t_peak = 3.0;  // window [1.125, 4.875] s, inside the record
  p.duration = 8.0;
  p.dt = 0.001;
  return p;
}

TEST(PulseShape, DerivativeOfVelocityIsAcceleration) {
  const PulseParameters p = test_pulse();
  const double w = 2.0 * std::numbers::pi / p.period, we = w / p.gamma;
  // v = A/2 [cos(w t + nu) + cos((w+we) t + nu)/2 + cos((w-we) t + nu)/2], so
  // |v'''| <= A/2 [w^3 + (w+we)^3/2 + (w-we)^3/2]. Central difference error <= h^2/6 |v'''|,
  // plus rounding ~ eps |v| / h. v is only C^1 at the window edges (v'' jumps), so points
  // within 2h of an edge are skipped.
  const double h = 1e-5;
  const double v3 =
      0.5 * p.amplitude * (std::pow(w, 3) + 0.5 * std::pow(w + we, 3) + 0.5 * std::pow(w - we, 3));
  const double tol = h * h / 6.0 * v3 + 4.0 * 2.2e-16 * p.amplitude / h;
  const double half = 0.5 * p.gamma * p.period;
  double worst = 0.0;
  int checked = 0;
  for (double t = 0.0; t <= p.duration; t += 0.00731) {
    if (std::abs(std::abs(t - p.t_peak) - half) < 2.0 * h) continue;
    const double numeric = (pulse_velocity(p, t + h) - pulse_velocity(p, t - h)) / (2.0 * h);
    worst = std::max(worst, std::abs(numeric - pulse_acceleration(p, t)));
    ++checked;
  }
  EXPECT_GT(checked, 1000);
  EXPECT_LT(worst, tol);
}

TEST(PulseShape, ZeroOutsideWindowAndContinuousAtEdges) {
  const PulseParameters p = test_pulse();
  const double half = 0.5 * p.gamma * p.period;
  for (double edge : {p.t_peak - half, p.t_peak + half}) {
    EXPECT_NEAR(pulse_velocity(p, edge), 0.0, 1e-15);
    EXPECT_NEAR(pulse_acceleration(p, edge), 0.0, 1e-14);
    EXPECT_NEAR(pulse_acceleration(p, edge - 1e-7), pulse_acceleration(p, edge + 1e-7), 1e-6);
  }
  EXPECT_EQ(pulse_velocity(p, 0.5), 0.0);
  EXPECT_EQ(pulse_acceleration(p, 6.0), 0.0);
  EXPECT_NEAR(pulse_velocity(p, p.t_peak), p.amplitude * std::cos(p.phase), 1e-15);
}

TEST(PulseMotion, SamplesAccelerationOnGrid) {
  const PulseParameters p = test_pulse();
  const GroundMotion m = make_pulse(p);
  EXPECT_EQ(m.name, "pulse");
  EXPECT_DOUBLE_EQ(m.dt, p.dt);
  ASSERT_EQ(m.acceleration.size(), 8001u);
  for (std::size_t k = 0; k < m.acceleration.size(); k += 37)
    EXPECT_EQ(m.acceleration[k], pulse_acceleration(p, static_cast<double>(k) * p.dt));
  EXPECT_NEAR(m.duration(), p.duration, 1e-12);
}

TEST(PulseMotion, IntegratedVelocityPeakMatchesAnalytic) {
  const PulseParameters p = test_pulse();
  const GroundMotionPeaks pk = peaks_of(make_pulse(p));
  // Analytic max |v| by dense sampling (step 1e-5 s: relative error ~ (w h)^2/8 ~ 1e-9).
  double vmax = 0.0, tmax = 0.0;
  for (double t = 0.0; t <= p.duration; t += 1e-5) {
    const double v = std::abs(pulse_velocity(p, t));
    if (v > vmax) {
      vmax = v;
      tmax = t;
    }
  }
  EXPECT_NEAR(pk.pgv, vmax, 1e-3 * vmax);
  EXPECT_NEAR(pk.t_pgv, tmax, 2.0 * p.dt);
  // Sanity: the analytic peak is a real pulse peak, not the envelope edge.
  EXPECT_GT(vmax, 0.5 * p.amplitude);
}

TEST(PulseValidation, RejectsBadParameters) {
  const PulseParameters good = test_pulse();
  auto with = [&](auto change) {
    PulseParameters p = good;
    change(p);
    return p;
  };
  EXPECT_THROW(make_pulse(with([](PulseParameters& p) { p.period = 0.0; })), std::invalid_argument);
  EXPECT_THROW(make_pulse(with([](PulseParameters& p) { p.period = std::nan(""); })),
               std::invalid_argument);
  EXPECT_THROW(make_pulse(with([](PulseParameters& p) { p.gamma = 1.0; })), std::invalid_argument);
  EXPECT_THROW(make_pulse(with([](PulseParameters& p) { p.dt = 0.0; })), std::invalid_argument);
  EXPECT_THROW(make_pulse(with([](PulseParameters& p) { p.dt = -0.01; })), std::invalid_argument);
  EXPECT_THROW(make_pulse(with([](PulseParameters& p) { p.duration = 0.0; })),
               std::invalid_argument);
  EXPECT_THROW(pulse_velocity(with([](PulseParameters& p) { p.gamma = 0.5; }), 1.0),
               std::invalid_argument);
  EXPECT_THROW(pulse_acceleration(with([](PulseParameters& p) { p.period = -2.0; }), 1.0),
               std::invalid_argument);
  try {
    make_pulse(with([](PulseParameters& p) { p.gamma = 1.0; }));
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gamma must be > 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace isopound
