// CSV fields for the project's result and index files: RFC 4180 quoting; newlines in a field become
// spaces.
#pragma once

#include <string>
#include <vector>

namespace crowdsim {

/// `s` as one CSV field, quoted (quotes doubled) only if it holds a comma, quote or newline.
std::string CsvField(const std::string& s);

/// The fields of one CSV line (quotes removed, doubled quotes undone, '\r' dropped).
std::vector<std::string> SplitCsvLine(const std::string& line);

}  // namespace crowdsim
