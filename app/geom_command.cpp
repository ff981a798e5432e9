// `isoparm geom [FILE]`: the JSON geometry protocol on a file or standard input.
#include <iostream>
#include <memory>
#include <unistd.h>

#include "app/commands.hpp"
#include "core/json/input_file.hpp"
#include "core/json/writer.hpp"
#include "core/protocol/protocol.hpp"

namespace isoparm::app {

Action register_geom_command(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "geom", "Answer JSON geometry requests (see docs/ and the geom protocol spec)");
    auto file = std::make_shared<std::string>();
    sub->add_option("FILE", *file, "request file (a JSON object or array); default: stdin");
    return [file]() -> int {
        // Read here, not through a stream: only a regular file is opened (a FIFO cannot block,
        // a directory or /proc/self/mem is a clean error) and no input beyond the cap is kept.
        geom::Expected<std::string> text =
            file->empty() ? json_io::read_descriptor(STDIN_FILENO, "standard input")
                          : json_io::read_input_file(*file);
        if (!text) {
            if (text.error().code == geom::ErrorCode::limit) {
                std::string s;
                json_io::write_json(s, protocol::input_error_response(text.error()));
                std::cout << s << "\n";
                return 1;
            }
            std::cerr << "isoparm geom: " << text.error().message << "\n";
            return 2;
        }
        return protocol::run_protocol_text(std::move(text).value(), std::cout, std::cerr);
    };
}

} // namespace isoparm::app
