// The desktop's files (see files.hpp): everything is on disk already.
#include "ui/platform/files.hpp"

namespace isoparm::ui::files {

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

bool copy_picture(const std::string&) {
    return false;
}

std::string unavailable(Feature) {
    return "";
}

} // namespace isoparm::ui::files
