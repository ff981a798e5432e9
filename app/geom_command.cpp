// `isoparm geom [FILE]`: the JSON geometry protocol on a file or standard input.
#include <fstream>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "core/doc/protocol.hpp"

namespace isoparm::app {

Action register_geom_command(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "geom", "Answer JSON geometry requests (see docs/ and the geom protocol spec)");
    auto file = std::make_shared<std::string>();
    sub->add_option("FILE", *file, "request file (a JSON object or array); default: stdin");
    return [file]() -> int {
        if (file->empty()) return doc::run_protocol(std::cin, std::cout, std::cerr);
        std::ifstream in(*file, std::ios::binary);
        if (!in) {
            std::cerr << "isoparm geom: cannot open '" << *file << "'\n";
            return 2;
        }
        return doc::run_protocol(in, std::cout, std::cerr);
    };
}

} // namespace isoparm::app
