// The clear-text encoding of ISO 10303-21 (a STEP "Part 21" file): numbered entity instances,
// strings, reals and lists, and the HEADER / DATA sections around them. It knows nothing of
// any schema; step_writer.* builds the AP214 entities with it.
#pragma once

#include <string>
#include <vector>

namespace isoparm::exchange::step {

// A Part 21 string literal: apostrophes doubled, backslashes doubled (both are escapes, ISO
// 10303-21 6.4.3), and anything outside printable ASCII replaced by '?' so that every reader
// takes the file whatever its \X2\ support.
std::string quoted(const std::string& text);

// "#12".
std::string ref(int id);

// "(a,b,c)": a Part 21 list of already encoded parameters.
std::string list(const std::vector<std::string>& items);

// Entity instances numbered #1, #2, ... in the order they are added.
class DataSection {
public:
    // `record` is everything after "#id=": "CARTESIAN_POINT('',(0.0,0.0,0.0))" for a simple
    // instance, "( BOUNDED_CURVE() B_SPLINE_CURVE(...) ... )" for a complex one. Returns id.
    int add(std::string record);
    int next_id() const { return static_cast<int>(records_.size()) + 1; }
    // The whole file: ISO-10303-21; HEADER (description, file name, schema); DATA; END-ISO.
    // The time stamp is fixed so that the same geometry always gives the same bytes.
    std::string file_text(const std::string& description, const std::string& name,
                          const std::string& schema) const;

private:
    std::vector<std::string> records_;
};

} // namespace isoparm::exchange::step
