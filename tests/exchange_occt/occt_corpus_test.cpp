// No file can take the program down: a corpus of mutated STEP and IGES files, made at test time
// from isoparm's own exports of every scene (bytes flipped, lines deleted, duplicated and
// swapped, files cut, references left dangling or pointing at themselves or each other, entity
// names garbled, numbers made nonsense, IGES degrees of 999), goes through the import path
// (scene::import_text, what `isoparm import`, File > Import and the `import` op call). Each
// import must end with objects or a clean error, with no temporary file left in TMPDIR, no
// descriptor left open and no child process left behind; OCCT's crashes stay in its sandbox.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <dirent.h>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <vector>

#include "core/exchange_occt/occt_reader.hpp"
#include "core/scene/export_document.hpp"
#include "core/scene/import_document.hpp"
#include "core/scene/scene_io.hpp"
#include "tests/support/temp_dir.hpp"

using namespace isoparm;

namespace {

struct Seed {
    std::string name;
    std::string text;
    scene::ImportFormat format;
};

// Every scene's exact objects (those with positive weights) as IGES and STEP.
std::vector<Seed> exported_seeds() {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(
             std::filesystem::path(ISOPARM_SOURCE_DIR) / "assets/scenes"))
        if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::vector<Seed> seeds;
    for (const auto& file : files) {
        const auto doc = scene::load_scene(file.string());
        if (!doc) continue;
        std::vector<const doc::Object*> objects;
        for (const doc::Object& o : doc->objects) {
            if (!o.surface() && !o.curve()) continue;
            const exchange::ExactShape shape =
                o.surface() ? exchange::ExactShape(*o.surface()) : exchange::ExactShape(*o.curve());
            if (exchange::check_positive_weights(shape)) objects.push_back(&o);
        }
        if (objects.empty()) continue;
        for (auto [format, import] :
             {std::pair{scene::ExportFormat::iges, scene::ImportFormat::iges},
              std::pair{scene::ExportFormat::step, scene::ImportFormat::step}}) {
            scene::ExportOptions options;
            options.format = format;
            options.name = file.stem().string();
            const auto out = scene::export_document(objects, options);
            if (out) seeds.push_back({file.stem().string(), out->bytes, import});
        }
    }
    return seeds;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        lines.push_back(text.substr(pos, end - pos + 1));
        pos = end + 1;
    }
    return lines;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l;
    return out;
}

// Where tokens start (`starts(text, k)`) and how far they run (`in` after the first character).
template <class Starts, class In>
std::vector<std::pair<std::size_t, std::size_t>> tokens(const std::string& text, Starts starts,
                                                        In in) {
    std::vector<std::pair<std::size_t, std::size_t>> found;
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (!starts(text, k)) continue;
        std::size_t end = k + 1;
        while (end < text.size() && in(text[end])) ++end;
        found.push_back({k, end - k});
        k = end - 1;
    }
    return found;
}

// One mutation of `text`; `what` says which, for failure messages.
std::string mutate(const Seed& seed, std::mt19937& rng, std::string& what) {
    auto pick = [&](std::size_t n) {
        return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
    };
    std::string text = seed.text;
    std::vector<std::string> lines = lines_of(text);
    const bool step = seed.format == scene::ImportFormat::step;
    const int kind = static_cast<int>(pick(11));
    switch (kind) {
    case 0: { // flip a few bytes
        const std::size_t n = 1 + pick(8);
        for (std::size_t k = 0; k < n; ++k) text[pick(text.size())] = static_cast<char>(pick(256));
        what = "flipped " + std::to_string(n) + " bytes";
        return text;
    }
    case 1: { // delete a line
        const std::size_t l = pick(lines.size());
        lines.erase(lines.begin() + static_cast<long>(l));
        what = "deleted line " + std::to_string(l + 1);
        return joined(lines);
    }
    case 2: { // duplicate a line
        const std::size_t l = pick(lines.size());
        lines.insert(lines.begin() + static_cast<long>(l), lines[l]);
        what = "duplicated line " + std::to_string(l + 1);
        return joined(lines);
    }
    case 3: { // swap two lines
        const std::size_t a = pick(lines.size()), b = pick(lines.size());
        std::swap(lines[a], lines[b]);
        what = "swapped lines " + std::to_string(a + 1) + " and " + std::to_string(b + 1);
        return joined(lines);
    }
    case 4: { // cut the file
        const std::size_t at = pick(text.size());
        what = "cut at byte " + std::to_string(at);
        return text.substr(0, at);
    }
    case 5: { // a number made nonsense
        static const char* const nonsense[] = {
            "1e999", "-1e999", "nan", "0.6X5", "-0", "1e-320", "99999999999999999999",
            "",      "1..2",   "-7"};
        const auto found = tokens(
            text,
            [](const std::string& t, std::size_t k) {
                return std::isdigit(static_cast<unsigned char>(t[k])) &&
                       (k == 0 || !std::isalnum(static_cast<unsigned char>(t[k - 1])));
            },
            [](char c) {
                return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'E' ||
                       c == 'e' || c == '-' || c == '+';
            });
        if (found.empty()) break;
        const auto [at, len] = found[pick(found.size())];
        const char* bad = nonsense[pick(std::size(nonsense))];
        what = "number at byte " + std::to_string(at) + " made '" + bad + "'";
        return text.replace(at, len, bad);
    }
    case 6:
    case 7: { // STEP: a reference dangling, to itself, or two entities citing each other;
              // IGES: a degree or count field made 999 or negative
        if (step) {
            // References (#N not followed by '='), not entity names.
            std::vector<std::pair<std::size_t, std::size_t>> refs;
            for (const auto& [at, len] : tokens(
                     text, [](const std::string&t, std::size_t k) { return t[k] == '#'; },
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }))
                if (at + len < text.size() && text[at + len] != '=') refs.push_back({at, len});
            if (refs.empty()) break;
            const auto [at, len] = refs[pick(refs.size())];
            // The entity this reference sits in.
            const std::size_t start = text.rfind("\n#", at);
            const std::string own = start == std::string::npos
                                        ? "#1"
                                        : text.substr(start + 1, text.find('=', start) - start - 1);
            const int how = static_cast<int>(pick(3));
            const std::string to = how == 0   ? "#987654"
                                   : how == 1 ? own
                                              : "#" + std::to_string(1 + pick(400));
            what = std::string(how == 0   ? "dangling"
                               : how == 1 ? "self"
                                          : "cyclic/other") +
                   " reference at byte " + std::to_string(at) + " -> " + to;
            return text.replace(at, len, to);
        }
        // IGES parameter data: the counts and degrees after "126," or "128,".
        const std::size_t at = text.find(pick(2) ? "128," : "126,");
        if (at == std::string::npos) break;
        const std::size_t field = at + 4;
        const std::size_t comma = text.find(',', field);
        static const char* const values[] = {"999", "-1", "0", "100000", "30"};
        const char* v = values[pick(std::size(values))];
        what = "IGES count/degree at byte " + std::to_string(field) + " made " + v;
        return text.replace(field, comma - field, v);
    }
    case 8: { // an entity name garbled (STEP) or an entity type changed (IGES)
        if (step) {
            static const char* const names[] = {
                "CARTESIAN_POINT", "B_SPLINE_SURFACE_WITH_KNOTS", "ADVANCED_FACE", "CLOSED_SHELL",
                "OPEN_SHELL",      "B_SPLINE_CURVE_WITH_KNOTS",   "EDGE_CURVE",    "VERTEX_POINT",
                "FACE_BOUND"};
            const std::string name = names[pick(std::size(names))];
            std::size_t at = text.find(name);
            if (at == std::string::npos) break;
            for (std::size_t skip = pick(20); skip > 0; --skip) {
                const std::size_t next = text.find(name, at + 1);
                if (next == std::string::npos) break;
                at = next;
            }
            what = name + " at byte " + std::to_string(at) + " garbled";
            return text.replace(at, name.size(),
                                name.substr(0, name.size() / 2) + "X" +
                                    name.substr(name.size() / 2));
        }
        std::vector<std::size_t> directory;
        for (std::size_t l = 0; l < lines.size(); ++l)
            if (lines[l].size() >= 73 && lines[l][72] == 'D') directory.push_back(l);
        if (directory.empty()) break;
        std::string& d = lines[directory[pick(directory.size())]];
        static const char* const types[] = {"     126", "     128", "     999", "      -5",
                                            "     144"};
        d.replace(0, 8, types[pick(std::size(types))]);
        what = "IGES directory entry type changed";
        return joined(lines);
    }
    case 9: { // a run of bytes removed from the middle
        const std::size_t at = pick(text.size()), n = 1 + pick(200);
        what = "removed " + std::to_string(n) + " bytes at " + std::to_string(at);
        return text.erase(at, n);
    }
    default: { // deep nesting: a list opened many times (STEP) or a huge count (IGES)
        if (step) {
            const std::size_t at = text.find("((");
            if (at == std::string::npos) break;
            what = "20000 nested parentheses";
            return text.insert(at, std::string(20000, '('));
        }
        const std::size_t at = text.find("128,");
        if (at == std::string::npos) break;
        what = "IGES surface with 2^31 - 1 control points";
        return text.replace(at + 4, text.find(',', at + 4) - at - 4, "2147483646");
    }
    }
    what = "flipped one byte (fallback)";
    text[pick(text.size())] ^= 0x20;
    return text;
}

std::size_t entries_in(const std::string& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
    return n;
}

std::size_t open_descriptors() {
    return entries_in("/proc/self/fd");
}

TEST(OcctImportCorpus, FiveHundredMutatedExportsImportWithoutACrashOrALeftover) {
    exchange_occt::install();
    test::TempDir tmp("isoparm-corpus-tmp");
    const char* old_tmpdir = std::getenv("TMPDIR");
    const std::string saved = old_tmpdir ? old_tmpdir : "";
    ::setenv("TMPDIR", tmp.dir().c_str(), 1);
    // A mutant that sends OCCT into an endless loop (a weight of 1e999 does) costs 2 s, not 10.
    ::setenv("ISOPARM_IMPORT_CPU_SECONDS", "2", 1);

    const std::vector<Seed> seeds = exported_seeds();
    ASSERT_GE(seeds.size(), 20u);
    std::mt19937 rng(20261127);
    constexpr int corpus = 520;
    const std::size_t fds_before = open_descriptors();
    int ok = 0, refused = 0, crashed = 0, left_out = 0;
    std::vector<std::string> crash_messages;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < corpus; ++k) {
        const Seed& seed = seeds[static_cast<std::size_t>(k) % seeds.size()];
        std::string what;
        const std::string text = mutate(seed, rng, what);
        const std::string label = "mutant " + std::to_string(k) + " of " + seed.name +
                                  (seed.format == scene::ImportFormat::iges ? ".igs" : ".stp") +
                                  ": " + what;
        // ISOPARM_CORPUS_DUMP=DIR keeps the corpus (to run another isoparm on it).
        if (const char* dump = std::getenv("ISOPARM_CORPUS_DUMP")) {
            std::ofstream(std::filesystem::path(dump) /
                              ("mutant-" + std::to_string(k) +
                               (seed.format == scene::ImportFormat::iges ? ".igs" : ".stp")),
                          std::ios::binary)
                << text;
        }
        const auto t0 = std::chrono::steady_clock::now();
        const auto r = scene::import_text(text, seed.format);
        const double took =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (took > 1) std::cout << "  " << took << " s: " << label << "\n";
        if (r) {
            ++ok;
            for (const std::string& s : r->skipped)
                left_out += s.find("; it is left out") != std::string::npos;
        } else {
            ++refused;
            EXPECT_FALSE(r.error().message.empty()) << label;
            if (std::getenv("ISOPARM_CORPUS_VERBOSE"))
                std::cout << "REFUSED " << label << ": " << r.error().message << "\n";
            if (r.error().message.find("crashed") != std::string::npos) {
                ++crashed;
                if (crash_messages.size() < 500)
                    crash_messages.push_back(label + ": " + r.error().message);
            }
        }
        EXPECT_EQ(entries_in(tmp.dir().string()), 0u) << label << " left a file in TMPDIR";
        int status = 0;
        EXPECT_LE(::waitpid(-1, &status, WNOHANG), 0) << label << " left a child process";
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(open_descriptors(), fds_before) << "descriptors left open";
    ::unsetenv("ISOPARM_IMPORT_CPU_SECONDS");
    if (saved.empty())
        ::unsetenv("TMPDIR");
    else
        ::setenv("TMPDIR", saved.c_str(), 1);
    auto cpu = [](int who) {
        struct rusage u {};
        ::getrusage(who, &u);
        return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
               static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
    };
    std::cout << "CPU: " << cpu(RUSAGE_SELF) << " s in this process, " << cpu(RUSAGE_CHILDREN)
              << " s in the readers' processes\n";
    std::cout << corpus << " mutated files (" << seeds.size() << " exports): " << ok
              << " imported, " << refused << " refused with a message (" << crashed
              << " of them after OCCT crashed in its sandbox), " << left_out
              << " faces or edges left out after a crash; " << seconds << " s\n";
    for (const std::string& m : crash_messages) std::cout << "  " << m << "\n";
    EXPECT_EQ(ok + refused, corpus);
}

} // namespace
