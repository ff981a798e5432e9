#include "core/exchange_occt/occt_reader.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <sys/mman.h>
#include <unistd.h>

#include "core/exchange/cad_text_check.hpp"
#include "core/exchange/import_wire.hpp"
#include "core/exchange/sandbox.hpp"
#include "core/exchange_occt/occt_read.hpp"
#include "core/json/out_of_memory.hpp"

namespace isoparm::exchange_occt {

namespace {

using exchange::CadFormat;
using geom::ErrorCode;

// The text as a file OCCT's IGES reader can open by name (it has no stream reader): an
// anonymous memory file (memfd) named through /proc/self/fd, so nothing is ever written to a
// disk and nothing can be left behind. Where memfd or /proc is missing, a private temporary
// file (mkstemp) that this process, which outlives every crash of the reader, removes.
class InputFile {
public:
    explicit InputFile(std::string_view text) {
        fd_ = ::memfd_create("isoparm-import", MFD_CLOEXEC);
        if (fd_ >= 0) {
            path_ = "/proc/self/fd/" + std::to_string(fd_);
            if (write_all(text) && ::access(path_.c_str(), R_OK) == 0) return;
            ::close(fd_);
            fd_ = -1;
        }
        const char* dir = std::getenv("TMPDIR");
        path_ = std::string(dir && *dir ? dir : "/tmp") + "/isoparm-import-XXXXXX";
        fd_ = ::mkstemp(path_.data());
        if (fd_ < 0) {
            error_ = std::strerror(errno);
            path_.clear();
            return;
        }
        temporary_ = true;
        if (!write_all(text)) error_ = std::strerror(errno);
    }
    ~InputFile() {
        if (temporary_) ::unlink(path_.c_str());
        if (fd_ >= 0) ::close(fd_);
    }
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;
    const std::string& path() const { return path_; }
    const std::string& error() const { return error_; }

private:
    bool write_all(std::string_view text) {
        return exchange::write_to_parent(fd_, text) && ::lseek(fd_, 0, SEEK_SET) == 0;
    }
    int fd_ = -1;
    std::string path_, error_;
    bool temporary_ = false;
};

const char* stage_text(int stage) {
    switch (stage) {
    case ReadProgress::starting:
    case ReadProgress::reading:
        return "reading the file";
    case ReadProgress::transferring:
        return "building its shapes";
    case ReadProgress::converting:
        return "converting its faces and edges";
    case ReadProgress::listing:
        return "listing what it could not transfer";
    default:
        return "finishing";
    }
}

// How the child ended, for a sentence: "crashed with signal 11 (SIGSEGV: Segmentation fault)".
std::string how_it_ended(const exchange::SandboxRun& run, const exchange::SandboxLimits& limits) {
    using Ending = exchange::SandboxRun::Ending;
    switch (run.ending) {
    case Ending::timed_out:
        return "took longer than " + geom::format_number(limits.wall_seconds) +
               " s and was stopped";
    case Ending::too_much:
        return "answered with more than " + std::to_string(limits.output_bytes >> 20) +
               " MiB of curves and surfaces (more than the " +
               std::to_string(exchange::max_import_control_points) +
               " control points one import takes) and was stopped";
    case Ending::signaled:
        if (run.signal == SIGXCPU || run.signal == SIGKILL)
            return "was stopped by " + exchange::describe_signal(run.signal) +
                   " (its CPU time limit is " + geom::format_number(limits.cpu_seconds) +
                   " s; its memory limit " + std::to_string(limits.memory_bytes >> 20) + " MiB)";
        return "crashed with " + exchange::describe_signal(run.signal);
    case Ending::exited:
        if (run.exit_status == 4)
            return "ran out of memory (its limit is " + std::to_string(limits.memory_bytes >> 20) +
                   " MiB)";
        if (run.exit_status != 0)
            return "failed (exit status " + std::to_string(run.exit_status) + ")";
        return "ended without finishing its answer";
    case Ending::not_started:
        break;
    }
    return "could not start: " + run.why_not_started;
}

// Items a crash may leave out before the whole file is given up: a file whose faces crash the
// reader one after another is not worth as many reads.
constexpr int max_crashed_items = 8;

// The child's limits for a file of `size` bytes.
exchange::SandboxLimits reader_limits(std::size_t size) {
    exchange::SandboxLimits limits = exchange::sandbox_limits_for(size);
    // The import's budget in bytes on the wire: its control points and weights (32 bytes each)
    // and twice that again for knots, names and records.
    limits.output_bytes = 3 * 32 * exchange::max_import_control_points;
    // ISOPARM_IMPORT_CPU_SECONDS: another CPU time limit (a slow machine, a huge file, a test).
    if (const char* v = std::getenv("ISOPARM_IMPORT_CPU_SECONDS")) {
        char* end = nullptr;
        const double seconds = std::strtod(v, &end);
        if (end != v && *end == '\0' && seconds > 0 && seconds < 1e6) {
            limits.cpu_seconds = seconds;
            limits.wall_seconds = exchange::wall_seconds_for(seconds);
        }
    }
    return limits;
}

// The answer a child out of memory writes: one error record.
std::string out_of_memory_wire() {
    exchange::ImportWireWriter w;
    w.take();
    w.error(geom::make_error(ErrorCode::limit, std::string(json_io::out_of_memory_message) +
                                                   " (OCCT's reader ran out of memory)"));
    w.done();
    return w.take();
}

// A child that finished its answer: the objects with every entity skipped, or its refusal.
geom::Expected<exchange::ImportResult> finished_reading(exchange::ImportWireReading& reading,
                                                        const exchange::CadTextCheck& check,
                                                        bool careful,
                                                        const std::string& whole_file_crash) {
    if (reading.error && careful) {
        // Not readable face by face either: the first crash is the answer.
        return geom::make_error(ErrorCode::parse,
                                "OpenCASCADE's STEP reader " + whole_file_crash +
                                    " while building its shapes, and the file cannot be "
                                    "read face by face instead (" +
                                    reading.error->message +
                                    "); nothing is imported (it ran in a process of "
                                    "its own, so isoparm itself is unaffected)");
    }
    if (reading.error) {
        // A cut file is the likelier reason for a reader's refusal: say it first.
        geom::Error e = *reading.error;
        for (const exchange::SkippedEntity& note : check.notes)
            e.message = note.reason + "; " + e.message;
        return e;
    }
    exchange::ImportResult out;
    out.skipped = check.notes;
    for (const exchange::BadEntity& bad : check.bad_entities)
        out.skipped.push_back({"IGES entity D" + std::to_string(bad.directory_line),
                               bad.reason + "; it is not read, and a face on it is lost"});
    out.objects = std::move(reading.result.objects);
    for (exchange::SkippedEntity& s : reading.result.skipped) out.skipped.push_back(std::move(s));
    return out;
}

// A child that ended without an answer, and was not read again: how and where it ended.
geom::Error reader_failure(const exchange::SandboxRun& run, CadFormat format,
                           const std::string& how, const ReadProgress& progress) {
    const int stage = progress.stage.load();
    const bool limit = run.ending == exchange::SandboxRun::Ending::timed_out ||
                       (run.ending == exchange::SandboxRun::Ending::signaled &&
                        (run.signal == SIGXCPU || run.signal == SIGKILL)) ||
                       (run.ending == exchange::SandboxRun::Ending::exited && run.exit_status == 4);
    std::string where = stage_text(stage);
    if (stage == ReadProgress::converting && progress.entity[0] != '\0')
        where += std::string(" (at ") + progress.entity + ")";
    return geom::make_error(limit ? ErrorCode::limit : ErrorCode::parse,
                            std::string("OpenCASCADE's ") +
                                (format == CadFormat::iges ? "IGES" : "STEP") + " reader " + how +
                                " while " + where +
                                "; nothing is imported (it ran in a process of its own, so "
                                "isoparm itself is unaffected)");
}

} // namespace

geom::Expected<exchange::ImportResult> read(std::string_view text, CadFormat format) {
    const exchange::CadTextCheck check = exchange::check_cad_text(text, format);
    if (check.not_the_format)
        return geom::make_error(ErrorCode::parse,
                                std::string(format == CadFormat::iges ? "it is not an IGES file: "
                                                                      : "it is not a STEP file: ") +
                                    check.why_not);
    // IGES B-spline entities whose numbers are garbled are read by nobody: OCCT would read
    // other numbers in their place (or crash on a degree of 999).
    // A STEP file cut short is completed after its last whole entity, so what is there is read.
    std::string cleaned;
    if (!check.bad_entities.empty())
        cleaned = exchange::iges_without_entities(text, check.bad_entities);
    else if (check.step_cut_short)
        cleaned = exchange::step_completed(text);
    ReadPlan plan;
    plan.text = cleaned.empty() ? text : std::string_view(cleaned);
    plan.format = format;
    plan.bad_entities = check.bad_entities;
    std::optional<InputFile> file;
    if (format == CadFormat::iges) {
        file.emplace(plan.text);
        if (!file->error().empty() || file->path().empty())
            return geom::make_error(ErrorCode::internal,
                                    "cannot hand the text to OCCT's IGES reader (" + file->error() +
                                        ")");
        plan.path = file->path();
    }
    const exchange::SandboxLimits limits = reader_limits(text.size());
    exchange::SharedWithChild<ReadProgress> progress;
    // Built here: a child out of memory may have none left to build it.
    const std::string out_of_memory_record = out_of_memory_wire();
    std::string whole_file_crash; // how the reader ended when it read the file whole
    for (int attempt = 0;; ++attempt) {
        progress.reset();
        const exchange::SandboxRun run = exchange::run_sandboxed(
            [&](int fd) {
                try {
                    read_with_occt(plan, *progress, [fd](std::string&& bytes, bool last) {
                        if (!exchange::write_to_parent(fd, bytes)) ::_exit(5);
                        // Everything is sent: the child ends without freeing OCCT's model.
                        if (last) ::_exit(0);
                    });
                } catch (const std::bad_alloc&) {
                    exchange::write_to_parent(fd, out_of_memory_record);
                }
            },
            limits);
        exchange::ImportWireReading reading = exchange::read_import_wire(run.output);
        const bool finished = run.ending == exchange::SandboxRun::Ending::exited &&
                              run.exit_status == 0 && reading.done && !reading.garbled;
        if (finished) return finished_reading(reading, check, plan.careful, whole_file_crash);
        const std::string how = how_it_ended(run, limits);
        const int stage = progress->stage.load();
        const std::int64_t item = progress->item.load();
        if (format == CadFormat::step && stage == ReadProgress::transferring && !plan.careful &&
            run.ending == exchange::SandboxRun::Ending::signaled && run.signal != SIGXCPU &&
            run.signal != SIGKILL) {
            // The transfer of the whole file crashed: read it again face by face, so that only
            // the faces that crash it are lost.
            plan.careful = true;
            whole_file_crash = how;
            continue;
        }
        if (stage == ReadProgress::converting && item >= 0 && attempt < max_crashed_items &&
            run.ending != exchange::SandboxRun::Ending::timed_out &&
            run.ending != exchange::SandboxRun::Ending::too_much) {
            // One face took the reader down: read again without it.
            plan.skip.push_back({item, "OCCT " + how + (plan.careful ? " reading" : " converting") +
                                           " it; it is left out"});
            continue;
        }
        return reader_failure(run, format, how, *progress);
    }
}

void install() {
    exchange::install_cad_reader(&read);
}

} // namespace isoparm::exchange_occt
