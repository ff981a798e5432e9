// `isoparm check EXERCISE SUBMISSION... [--csv FILE] [--json FILE] [--threads N]`: grades
// students' scene files against an exercise (core/scene/exercise.hpp), a folder standing for
// its *.json files, on all cores: one line per submission, then a summary. Exit status: 0
// every submission passes; 1 one fails (an unreadable or malformed submission is a failure
// with its reason); 2 the exercise cannot be read, or the command line is wrong.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "app/commands.hpp"
#include "core/scene/atomic_file.hpp"
#include "core/scene/grading.hpp"
#include "core/scene/scene_io.hpp"

namespace isoparm::app {

namespace {

struct CheckOptions {
    std::string exercise;
    std::vector<std::string> submissions;
    std::string csv, json;
    int threads = 0;
    bool quiet = false;
};

int run(const CheckOptions& o) {
    const std::string name = "isoparm check: ";
    if (o.submissions.empty()) {
        std::cerr << name
                  << "name at least one submission (a scene file or a folder of them) "
                     "after the exercise\n";
        return 2;
    }
    if (o.threads < 0) {
        std::cerr << name << "--threads is 0 (every core) or more, got " << o.threads << "\n";
        return 2;
    }
    std::vector<std::string> inputs{o.exercise};
    inputs.insert(inputs.end(), o.submissions.begin(), o.submissions.end());
    for (const std::string& out : {o.csv, o.json}) {
        if (out.empty()) continue;
        geom::Status usable = scene::check_output_path(out);
        if (usable) usable = scene::check_output_is_not_input(out, inputs);
        if (!usable) {
            std::cerr << name << out << ": " << usable.error().message << "\n";
            return 2;
        }
    }
    auto exercise = scene::load_exercise(o.exercise);
    if (!exercise) {
        const geom::Error& e = exercise.error();
        std::cerr << name << o.exercise << ": " << e.message
                  << (e.has_path && !e.path.empty() ? " (at " + e.path + ")" : "") << "\n";
        return 2;
    }
    const std::vector<std::string> files = scene::expand_submissions(o.submissions);
    if (files.empty()) {
        std::cerr << name << "no submissions found (the folders hold no .json files)\n";
        return 1;
    }
    const int threads = o.threads > 0
                            ? o.threads
                            : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const auto started = std::chrono::steady_clock::now();
    const std::vector<scene::SubmissionGrade> grades =
        scene::grade_files(*exercise, files, threads);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    bool all = true;
    for (const scene::SubmissionGrade& g : grades) {
        all = all && g.passed();
        if (!o.quiet || !g.passed()) std::cout << scene::grade_line(g) << "\n";
    }
    char timing[96];
    std::snprintf(timing, sizeof timing, " (graded in %.2f s on %d %s)", seconds, threads,
                  threads == 1 ? "thread" : "threads");
    std::cout << scene::grade_summary(grades) << timing << "\n";
    int status = all ? 0 : 1;
    auto write = [&](const std::string& path, const std::string& bytes) {
        if (path.empty()) return;
        if (geom::Status st = scene::write_file_atomically(path, bytes); !st) {
            std::cerr << name << st.error().message << "\n";
            status = 2;
        }
    };
    write(o.csv, scene::grades_csv(*exercise, grades));
    write(o.json, scene::pretty_json_text(scene::grades_json(*exercise, grades)));
    return status;
}

} // namespace

Action register_check_command(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "check", "Grade students' scene files against an exercise: a line per submission and a "
                 "summary (exit 0 all pass, 1 some fail, 2 bad exercise or usage)");
    auto o = std::make_shared<CheckOptions>();
    sub->add_option("EXERCISE", o->exercise, "the exercise (assets/exercises/NAME.json)")
        ->required();
    sub->add_option("SUBMISSION", o->submissions,
                    "scene files, or folders standing for their *.json files");
    sub->add_option("--csv", o->csv, "also write the grades as CSV, one row per submission");
    sub->add_option("--json", o->json, "also write the grades as JSON, with every check");
    sub->add_option("--threads", o->threads, "threads to grade with (default 0: every core)");
    sub->add_flag("--quiet", o->quiet, "print only the failures and the summary");
    return [o]() { return run(*o); };
}

} // namespace isoparm::app
