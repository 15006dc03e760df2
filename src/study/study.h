// study.h: a parameter study as its file describes it ('swarf sweep'): the study file read
// and expanded into cases, each case's overrides, and the check that every case reads. The
// runner (sweep.h), the record of a study's folder (study_record.h) and the study table
// (study_table.h) take a Study; the study file is described in docs/studies.md.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace swarf {

/// One case of a study: the overrides that make it.
struct StudyCase {
  std::string id;                             ///< "0000", "0001", ...: the folder DIR/cases/<id>
  std::map<std::string, std::string> values;  ///< varied key (and seed key) -> TOML value text
  int repetition = 0;                         ///< 0-based repetition (seed = seed_start + repetition)
};

/// A study file, expanded into its cases.
struct Study {
  std::string file;                          ///< the study file as given
  std::string title;                         ///< key 'title' (may be empty)
  std::string base;                          ///< key 'base' as written
  std::string base_path;                     ///< 'base' resolved against the study file's directory
  std::string base_hash;                     ///< FNV-1a 64-bit hash of the base case text, hex
  std::map<std::string, std::string> fixed;  ///< [set]: key -> TOML value text, applied to every case
  std::vector<std::string> parameters;       ///< the varied keys in column order (seed key last)
  std::map<std::string, std::string> units;  ///< [units]: key -> unit text for the study.csv header
  int repetitions = 1;
  std::string seed_key;  ///< case key set to seed_start + repetition (empty: none)
  long long seed_start = 1;
  bool plots = true;
  double case_time_limit = 0;  ///< s of wall time per case; 0 = none. A case past it is stopped (SIGTERM, then SIGKILL)
  std::vector<std::string> plot_metrics;  ///< empty = the default subset (see study_table.h)
  std::vector<std::string> plot_against;  ///< empty = the numeric varied keys
  std::vector<StudyCase> cases;           ///< in id order
};

/// Parses and expands a study file's text (directory: where 'base' is resolved). Throws
/// InputError naming the file, the key and the value.
Study parse_study(const std::string& text, const std::string& source, const std::string& directory);
/// Reads and expands a study file; also reads the base case and hashes it.
Study load_study(const std::string& path);

/// The --set arguments of a case ("key=value"): the [set] keys, then the varied ones.
std::vector<std::string> case_overrides(const Study& study, const StudyCase& c);
/// Reads the base case with every case's overrides, so a bad key stops the study before it runs.
void check_cases(const Study& study);

}  // namespace swarf
