// study_record.h: a study's record in its output folder: DIR/study.json (the expanded study,
// so that a rerun resumes with the same case ids), and each case's state read from its
// DIR/cases/<id>/summary.json.
#pragma once

#include <string>

#include "study/study.h"

namespace swarf {

/// Compares with DIR/study.json of an earlier run: known cases keep their ids, new ones are
/// numbered after them. Throws InputError naming the keys when the change would invalidate
/// finished cases (base case text, [set], seed key, a removed case). No study.json: no change.
void reconcile_study(Study& study, const std::string& out_dir);
void write_study_json(const Study& study, const std::string& out_dir);
/// The expanded study recorded by 'swarf sweep' in DIR/study.json.
Study read_study_json(const std::string& out_dir);

enum class CaseState { completed, failed, interrupted, not_run };
struct CaseStatus {
  CaseState state = CaseState::not_run;
  int exit_code = 0;         ///< failed: the exit code (128 + signal when killed by a signal)
  std::string log_tail;      ///< failed: the last lines of log.txt
  std::string text() const;  ///< "completed", "failed (exit 3)", "interrupted", "not run"
};
std::string case_dir(const std::string& out_dir, const StudyCase& c);
/// Completed only if DIR/cases/<id>/summary.json parses, says "completed" and was run with
/// this case's overrides.
CaseStatus case_status(const Study& study, const StudyCase& c, const std::string& out_dir);

}  // namespace swarf
