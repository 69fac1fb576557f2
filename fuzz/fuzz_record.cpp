// libFuzzer target: the ground-motion record readers (PEER .AT2 and plain columns). The first
// byte chooses how the file is read (format auto/PEER/columns, the file's extension, the
// acceleration and time columns, a dt), the rest is the file. Only RecordError (exit 2) may
// escape; anything else is a finding.
#include <cstdint>
#include <string>

#include "fuzz/fuzz_support.h"
#include "solver/excitation/ground_motion.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace isopound;
  if (size == 0) return 0;
  const unsigned choice = data[0];
  RecordReadOptions options;
  using Format = RecordReadOptions::Format;
  options.format = choice % 3 == 0   ? Format::kAuto
                   : choice % 3 == 1 ? Format::kPeer
                                     : Format::kColumns;
  options.column = static_cast<int>((choice >> 2) % 3);
  options.time_column = static_cast<int>((choice >> 4) % 4) - 1;  // -1: none
  options.dt = (choice & 0x40) ? 0.01 : 0.0;
  const char* name = (choice & 0x80) ? "record.AT2" : "record.txt";
  const std::string path =
      fuzz::write_scratch(name, reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    if (choice % 3 == 0) (void)sniff_record_format(path);
    const GroundMotion motion = read_record(path, options);
    (void)peaks_of(motion);
  } catch (const RecordError&) {
  }
  return 0;
}
