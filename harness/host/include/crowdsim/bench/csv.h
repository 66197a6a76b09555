// CSV fields as every result and index file of the project writes and reads them (RFC 4180
// quoting; newlines inside a field become spaces so a record stays on one line).
#pragma once

#include <string>
#include <vector>

namespace crowdsim {

/// `s` as one CSV field: quoted (with doubled quotes) only when it holds a comma, quote or
/// newline.
std::string CsvField(const std::string& s);

/// The fields of one CSV line (quotes removed, doubled quotes undone, '\r' dropped).
std::vector<std::string> SplitCsvLine(const std::string& line);

}  // namespace crowdsim
