// The desktop's files (see files.hpp): everything is on disk already; pictures reach the
// clipboard through the desktop's own tools.
#include "ui/platform/files.hpp"

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace isoparm::ui::files {

namespace fs = std::filesystem;

bool in_browser() {
    return false;
}

void request_upload(Purpose, const std::string&) {}

std::optional<Upload> take_upload() {
    return std::nullopt;
}

void hand_over(const std::string&) {}

void keep_settings() {}

void keep_recovery() {}

// The desktop's own tool (GLFW's clipboard holds text only): xclip on X11, wl-copy on Wayland.
std::string copy_picture(const std::string& png) {
    std::vector<std::vector<std::string>> tools;
    if (std::getenv("WAYLAND_DISPLAY")) tools.push_back({"wl-copy", "--type", "image/png"});
    if (std::getenv("DISPLAY"))
        tools.push_back({"xclip", "-selection", "clipboard", "-t", "image/png", "-i"});
    for (const auto& tool : tools) {
        bool found = false;
        if (const char* path = std::getenv("PATH")) {
            std::string dirs = path;
            std::size_t start = 0;
            while (start <= dirs.size() && !found) {
                const std::size_t end = dirs.find(':', start);
                const std::string dir = dirs.substr(start, end - start);
                found = ::access((fs::path(dir) / tool[0]).c_str(), X_OK) == 0;
                if (end == std::string::npos) break;
                start = end + 1;
            }
        }
        if (!found) continue;
        int fds[2];
        if (::pipe(fds) != 0) return "cannot start " + tool[0];
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
        posix_spawn_file_actions_addclose(&actions, fds[1]);
        std::vector<char*> argv;
        for (const std::string& a : tool) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        pid_t pid = 0;
        const int spawned =
            posix_spawnp(&pid, tool[0].c_str(), &actions, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&actions);
        ::close(fds[0]);
        if (spawned != 0) {
            ::close(fds[1]);
            return "cannot start " + tool[0];
        }
        // A tool that stops reading must not kill the workstation with SIGPIPE.
        struct sigaction ignore {
        }, old{};
        ignore.sa_handler = SIG_IGN;
        sigaction(SIGPIPE, &ignore, &old);
        std::size_t written = 0;
        while (written < png.size()) {
            const ssize_t n = ::write(fds[1], png.data() + written, png.size() - written);
            if (n <= 0) break;
            written += static_cast<std::size_t>(n);
        }
        ::close(fds[1]);
        sigaction(SIGPIPE, &old, nullptr);
        int status = 0;
        ::waitpid(pid, &status, 0); // xclip forks to serve the selection; the parent returns
        if (written < png.size() || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
            return tool[0] + " did not take the picture";
        return "";
    }
    return "no clipboard for pictures here: install xclip (X11) or wl-clipboard (Wayland)";
}

std::string unavailable(Feature) {
    return "";
}

} // namespace isoparm::ui::files
