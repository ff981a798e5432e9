// Files from the user's computer (see uploads.hpp).
#include "ui/uploads.hpp"

#include "ui/actions.hpp"
#include "ui/course_actions.hpp"
#include "ui/exchange_actions.hpp"
#include "ui/fit_actions.hpp"
#include "ui/platform/files.hpp"

namespace isoparm::ui {

bool request_upload_for(FileDialog::Mode mode) {
    using Mode = FileDialog::Mode;
    using files::Purpose;
    switch (mode) {
    case Mode::open:
        files::request_upload(Purpose::open_scene, ".json");
        return true;
    case Mode::open_lesson:
        files::request_upload(Purpose::open_lesson, ".json");
        return true;
    case Mode::import_file:
        files::request_upload(Purpose::import_file, ".step,.stp,.igs,.iges,.obj");
        return true;
    case Mode::load_points:
        files::request_upload(Purpose::load_points, ".csv,.xyz,.txt");
        return true;
    case Mode::open_exercise:
        files::request_upload(Purpose::open_exercise, ".json");
        return true;
    default:
        return false;
    }
}

void receive_uploads(AppContext& ctx) {
    while (const std::optional<files::Upload> u = files::take_upload()) {
        std::string error;
        switch (u->purpose) {
        case files::Purpose::open_scene:
            open_file(ctx, u->path); // File > Open asked about unsaved changes already
            break;
        case files::Purpose::open_lesson:
            request_open_lesson(ctx, u->path);
            break;
        case files::Purpose::import_file:
            if (!import_objects(ctx, u->path, error)) show_error(ctx, "Could not import", error);
            break;
        case files::Purpose::load_points:
            if (!load_fit_points(ctx, u->path, error))
                show_error(ctx, "Could not load the data points", error);
            break;
        case files::Purpose::open_exercise:
            request_open_exercise(ctx, u->path);
            break;
        }
    }
}

} // namespace isoparm::ui
