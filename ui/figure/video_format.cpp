// The animation format a file name asks for, the same in the desktop and the browser builds
// (the browser then says it has no encoder, browser_stand_ins.cpp).
#include <algorithm>
#include <cctype>

#include "ui/figure/video_encoder.hpp"

namespace isoparm::ui {

bool video_format_of(const std::string& path, VideoFormat& format) {
    std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".gif")
        format = VideoFormat::gif;
    else if (ext == ".mp4")
        format = VideoFormat::mp4;
    else
        return false;
    return true;
}

} // namespace isoparm::ui
