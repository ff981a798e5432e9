// Grading a class (`isoparm check EXERCISE SUBMISSION...`): every submission (a scene file)
// read and graded on all cores, and the grades as text lines, CSV and JSON. A submission that
// cannot be read is a failed grade with its reason, never a stop.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/scene/exercise.hpp"

namespace isoparm::scene {

struct SubmissionGrade {
    std::string file;
    std::string error; // why it could not be read or graded ("" when it was graded)
    Grade grade;
    bool passed() const { return error.empty() && grade.passed(); }
};

// The files named: a folder stands for its *.json files (sorted, not recursive); a name that
// is neither a file nor a folder is kept, and its grade says it cannot be read.
std::vector<std::string> expand_submissions(const std::vector<std::string>& names);

// Grades each file with `threads` threads (0: every core), in the order given.
std::vector<SubmissionGrade> grade_files(const Exercise& exercise,
                                         const std::vector<std::string>& files, int threads = 0);

// "PASS  alice.json  (5/5)" or "FAIL  bob.json  (3/5): <first failure>. Hint: <hint>".
std::string grade_line(const SubmissionGrade& g);
// "300 submissions: 270 passed, 30 failed (2 could not be read)".
std::string grade_summary(const std::vector<SubmissionGrade>& grades);
// One row per submission: file, result (pass / fail / unreadable), checks passed, checks,
// first failure (its label), message; then one column per check (1 / 0). RFC 4180 quoting.
std::string grades_csv(const Exercise& exercise, const std::vector<SubmissionGrade>& grades);
// {"exercise": title, "checks": [labels], "submissions": [{file, passed, error?, checks:
// [{label, passed, message?}]}], "summary": {submissions, passed, failed, unreadable}}.
nlohmann::json grades_json(const Exercise& exercise, const std::vector<SubmissionGrade>& grades);

} // namespace isoparm::scene
