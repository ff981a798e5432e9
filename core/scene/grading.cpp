// Grading many submissions: each is independent, so they are shared out across the cores.
#include "core/scene/grading.hpp"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <new>
#include <thread>

#include "core/geom/worker_pool.hpp"
#include "core/scene/scene_io.hpp"

namespace isoparm::scene {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string out = "\"";
    for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return out + "\"";
}

SubmissionGrade grade_one(const Exercise& exercise, const std::string& file) {
    SubmissionGrade g;
    g.file = file;
    try {
        auto doc = load_scene(file);
        if (!doc) {
            const geom::Error& e = doc.error();
            g.error = e.message + (e.has_path && !e.path.empty() ? " (at " + e.path + ")" : "");
            return g;
        }
        g.grade = grade(exercise, *doc);
    } catch (const std::bad_alloc&) {
        g.error = "out of memory while grading it";
    } catch (const std::exception& e) {
        g.error = std::string("could not be graded: ") + e.what();
    }
    return g;
}

} // namespace

std::vector<std::string> expand_submissions(const std::vector<std::string>& names) {
    std::vector<std::string> out;
    for (const std::string& name : names) {
        std::error_code ec;
        if (!fs::is_directory(name, ec)) {
            out.push_back(name);
            continue;
        }
        std::vector<std::string> inside;
        for (fs::directory_iterator it(name, ec), end; !ec && it != end; it.increment(ec))
            if (it->path().extension() == ".json" && !it->is_directory(ec))
                inside.push_back(it->path().string());
        std::sort(inside.begin(), inside.end());
        out.insert(out.end(), inside.begin(), inside.end());
    }
    return out;
}

std::vector<SubmissionGrade> grade_files(const Exercise& exercise,
                                         const std::vector<std::string>& files, int threads) {
    std::vector<SubmissionGrade> out(files.size());
    if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    geom::WorkerPool::shared().run(static_cast<int>(files.size()), threads, [&](int k) {
        out[static_cast<std::size_t>(k)] = grade_one(exercise, files[static_cast<std::size_t>(k)]);
    });
    return out;
}

std::string grade_line(const SubmissionGrade& g) {
    if (!g.error.empty()) return "FAIL  " + g.file + "  (cannot be read): " + g.error;
    const std::string count = "(" + std::to_string(g.grade.passed_count()) + "/" +
                              std::to_string(g.grade.checks.size()) + ")";
    if (g.grade.passed()) return "PASS  " + g.file + "  " + count;
    const CheckResult* f = g.grade.first_failure();
    std::string line = "FAIL  " + g.file + "  " + count + ": " + f->message;
    if (!f->hint.empty()) line += ". Hint: " + f->hint;
    return line;
}

std::string grade_summary(const std::vector<SubmissionGrade>& grades) {
    std::size_t passed = 0, unreadable = 0;
    for (const SubmissionGrade& g : grades) {
        passed += g.passed();
        unreadable += !g.error.empty();
    }
    std::string s =
        std::to_string(grades.size()) + (grades.size() == 1 ? " submission: " : " submissions: ") +
        std::to_string(passed) + " passed, " + std::to_string(grades.size() - passed) + " failed";
    if (unreadable) s += " (" + std::to_string(unreadable) + " could not be read)";
    return s;
}

std::string grades_csv(const Exercise& exercise, const std::vector<SubmissionGrade>& grades) {
    std::string out = "file,result,checks_passed,checks,first_failure,message";
    for (const Check& c : exercise.checks) out += "," + csv_field(c.label);
    out += "\n";
    for (const SubmissionGrade& g : grades) {
        const CheckResult* f = g.error.empty() ? g.grade.first_failure() : nullptr;
        out += csv_field(g.file) + "," +
               (!g.error.empty() ? "unreadable"
                : g.passed()     ? "pass"
                                 : "fail") +
               "," + std::to_string(g.grade.passed_count()) + "," +
               std::to_string(exercise.checks.size()) + "," + csv_field(f ? f->label : "") + "," +
               csv_field(!g.error.empty() ? g.error
                         : f              ? f->message
                                          : "");
        for (std::size_t k = 0; k < exercise.checks.size(); ++k)
            out += k < g.grade.checks.size() && g.grade.checks[k].passed ? ",1" : ",0";
        out += "\n";
    }
    return out;
}

json grades_json(const Exercise& exercise, const std::vector<SubmissionGrade>& grades) {
    json checks = json::array();
    for (const Check& c : exercise.checks) checks.push_back(c.label);
    json subs = json::array();
    std::size_t passed = 0, unreadable = 0;
    for (const SubmissionGrade& g : grades) {
        json s = {{"file", g.file}, {"passed", g.passed()}};
        if (!g.error.empty()) s["error"] = g.error;
        json results = json::array();
        for (const CheckResult& r : g.grade.checks) {
            json c = {{"label", r.label}, {"passed", r.passed}};
            if (!r.passed) c["message"] = r.message;
            results.push_back(std::move(c));
        }
        s["checks"] = std::move(results);
        subs.push_back(std::move(s));
        passed += g.passed();
        unreadable += !g.error.empty();
    }
    return {{"exercise", exercise.title},
            {"checks", std::move(checks)},
            {"submissions", std::move(subs)},
            {"summary",
             {{"submissions", grades.size()},
              {"passed", passed},
              {"failed", grades.size() - passed},
              {"unreadable", unreadable}}}};
}

} // namespace isoparm::scene
