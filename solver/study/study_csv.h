// Text forms shared by the study tables: numbers in their shortest round-trip decimal form (the
// same bits give the same text on every machine and thread count) and RFC 4180 CSV fields.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace isopound {

// Shortest decimal text that reads back to exactly `value` ("0.0105", "2500000000", "1e-05");
// NaN gives "" (an empty CSV cell), infinities "inf" / "-inf".
std::string format_number(double value);

// A CSV field: quoted (with "" for ") when it holds a comma, quote, CR or LF.
std::string csv_field(std::string_view text);

// One CSV line (fields joined with ',', ended by '\n').
std::string csv_line(const std::vector<std::string>& fields);

}  // namespace isopound
