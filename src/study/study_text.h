// study_text.h: small text helpers shared by the study's files (study_file.cpp,
// study_record.cpp, sweep.cpp): reading a file whole, naming a case's values, case ids and
// a log's last lines.
#pragma once

#include <map>
#include <string>

namespace swarf::study_text {

/// The whole file; throws InputError if it cannot be read.
std::string read_text(const std::string& path);
/// "key=value, key=value" of a case's varied values, in key order.
std::string describe(const std::map<std::string, std::string>& values);
/// Case number n as a zero-padded id of 'width' digits.
std::string case_id(long long n, int width);
/// The digits case ids of a study of 'count' cases get (at least 4).
int id_width(long long count);
/// The last 'lines' lines of a log (progress lines rewritten with '\r' shown as they ended), at most 2,000 characters.
std::string log_tail(const std::string& path, int lines);

}  // namespace swarf::study_text
