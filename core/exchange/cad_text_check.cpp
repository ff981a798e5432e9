#include "core/exchange/cad_text_check.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <optional>
#include <unordered_map>

namespace isoparm::exchange {

namespace {

// ---------------------------------------------------------------------------------------
// IGES: fixed 80-column records, the section letter in column 73 (IGES 5.3, 2.2.4).

struct Record {
    std::string_view text; // without the line break
    long line = 0;         // 1-based, for messages
};

std::vector<Record> records_of(std::string_view text) {
    std::vector<Record> out;
    if (text.find('\n') == std::string_view::npos && text.size() >= 80) {
        // Some writers put the 80-column records one after the other with no line breaks.
        for (std::size_t k = 0; k + 80 <= text.size(); k += 80)
            out.push_back({text.substr(k, 80), static_cast<long>(out.size() + 1)});
        return out;
    }
    long line = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view r = text.substr(pos, end - pos);
        if (!r.empty() && r.back() == '\r') r.remove_suffix(1);
        ++line;
        if (!r.empty()) out.push_back({r, line});
        pos = end + 1;
    }
    return out;
}

char section_of(const Record& r) {
    return r.text.size() >= 73 ? r.text[72] : '\0';
}

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// An integer field of a record (columns first..first+width-1, 1-based), or -1.
long field(const Record& r, std::size_t first, std::size_t width) {
    if (r.text.size() < first - 1 + width) return -1;
    const std::string_view f = trimmed(r.text.substr(first - 1, width));
    long v = 0;
    const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (f.empty() || ec != std::errc() || end != f.data() + f.size()) return -1;
    return v;
}

// IGES numbers (2.2.2.2 and 2.2.2.3): an optional sign, digits with at most one point, and an
// exponent E or D with an optional sign and digits. At least one digit before the exponent.
bool is_iges_number(std::string_view t) {
    std::size_t k = 0;
    if (k < t.size() && (t[k] == '+' || t[k] == '-')) ++k;
    int digits = 0;
    bool point = false;
    for (; k < t.size(); ++k) {
        if (t[k] >= '0' && t[k] <= '9')
            ++digits;
        else if (t[k] == '.' && !point)
            point = true;
        else
            break;
    }
    if (digits == 0) return false;
    if (k == t.size()) return true;
    if (t[k] != 'E' && t[k] != 'e' && t[k] != 'D' && t[k] != 'd') return false;
    ++k;
    if (k < t.size() && (t[k] == '+' || t[k] == '-')) ++k;
    const std::size_t exponent = k;
    while (k < t.size() && t[k] >= '0' && t[k] <= '9') ++k;
    return k == t.size() && k > exponent;
}

std::optional<long> iges_integer(std::string_view t) {
    long v = 0;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || ec != std::errc() || end != t.data() + t.size()) return std::nullopt;
    return v;
}

std::string shown(std::string_view t) {
    std::string s;
    for (char c : t.substr(0, 24))
        s.push_back(static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c);
    return "'" + s + (t.size() > 24 ? "...'" : "'");
}

// The parameter and record delimiters (Global parameters 1 and 2; ',' and ';' by default).
std::pair<char, char> delimiters(std::string_view global) {
    char param = ',', record = ';';
    std::size_t k = 0;
    if (global.substr(0, 2) == "1H" && global.size() >= 3) {
        param = global[2];
        k = 3;
    }
    if (k < global.size() && global[k] == param) ++k;
    if (global.substr(k, 2) == "1H" && global.size() >= k + 3) record = global[k + 2];
    return {param, record};
}

// Geom_BSplineCurve::MaxDegree() and Geom_BSplineSurface::MaxDegree() (OCCT 7.6): a higher one
// makes OpenCASCADE's IGES entity reader misbehave before any check of its own can run.
constexpr long max_reader_degree = 25;

// How many parameters entity 126 or 128 needs after its type, from its leading integers
// (IGES 5.3 4.23, 4.24), or the reason they are not counts.
struct Needed {
    long count = 0;
    std::string problem;
};
Needed needed_parameters(int type, const std::vector<std::string_view>& tokens) {
    const int ints = type == 126 ? 6 : 9;
    if (static_cast<int>(tokens.size()) < 1 + ints)
        return {0, "its parameter data ends after " + std::to_string(tokens.size()) +
                       " values, before its counts and degrees"};
    long v[9] = {};
    for (int k = 0; k < ints; ++k) {
        const auto n = iges_integer(trimmed(tokens[1 + k]));
        if (!n)
            return {0, "parameter " + std::to_string(k + 1) + " " + shown(tokens[1 + k]) +
                           " is not an integer"};
        v[k] = *n;
    }
    // 126: K (upper index: K + 1 control points) and M (degree); 128: K1, K2, M1, M2. A
    // curve's second direction reads as one more of the first.
    const long K = v[0], M = type == 126 ? v[1] : v[2];
    const long K2 = type == 126 ? K : v[1], M2 = type == 126 ? M : v[3];
    if (K < 0 || K2 < 0)
        return {0, "its upper index " + std::to_string(K < 0 ? K : K2) + " is negative"};
    if (M < 1 || M2 < 1) return {0, "its degree " + std::to_string(M < 1 ? M : M2) + " is below 1"};
    if (M > max_reader_degree || M2 > max_reader_degree)
        return {0,
                "its degree " + std::to_string(std::max(M, M2)) + " is above " +
                    std::to_string(max_reader_degree) +
                    ", the highest OpenCASCADE's B-splines take (isoparm reads IGES through it)"};
    if (K < M || K2 < M2)
        return {0, std::to_string((K < M ? K : K2) + 1) +
                       " control points are too few for degree " + std::to_string(K < M ? M : M2)};
    // Counts beyond isoparm's limits need not be totalled up: the reader refuses them.
    constexpr long cap = 1 << 20;
    if (K > cap || K2 > cap) return {-1, ""};
    // A 126's unit normal (the last three values) only matters for a planar curve, and writers
    // leave it out as trailing defaults (IGES 5.3 2.2.4.5.2).
    if (type == 126) return {ints + (K + M + 2) + (K + 1) * 4 + 2, ""};
    return {ints + (K + M + 2) + (K2 + M2 + 2) + (K + 1) * (K2 + 1) * 4 + 4, ""};
}

void check_bspline_entity(int type, int de_line, std::string_view data, char param, char record,
                          std::vector<BadEntity>& bad) {
    std::vector<std::string_view> tokens;
    std::size_t start = 0;
    bool ended = false;
    for (std::size_t k = 0; k < data.size(); ++k) {
        if (data[k] != param && data[k] != record) continue;
        tokens.push_back(data.substr(start, k - start));
        start = k + 1;
        if (data[k] == record) {
            ended = true;
            break;
        }
    }
    if (!ended) {
        bad.push_back({de_line, "its parameter data has no record delimiter '" +
                                    std::string(1, record) + "' (cut short)"});
        return;
    }
    const Needed need = needed_parameters(type, tokens);
    if (!need.problem.empty()) {
        bad.push_back({de_line, need.problem});
        return;
    }
    const long have = static_cast<long>(tokens.size()) - 1;
    if (need.count > 0 && have < need.count) {
        bad.push_back({de_line, "its parameter data holds " + std::to_string(have) +
                                    " values where its counts and degrees need " +
                                    std::to_string(need.count)});
        return;
    }
    const long check = need.count > 0 ? need.count : have;
    for (long k = 1; k <= check; ++k) {
        const std::string_view t = trimmed(tokens[static_cast<std::size_t>(k)]);
        if (!is_iges_number(t)) {
            bad.push_back({de_line, "parameter " + std::to_string(k) + " " + shown(t) +
                                        (t.empty() ? " is empty (a coefficient, not a default)"
                                                   : " is not a number")});
            return;
        }
    }
}

CadTextCheck check_iges(std::string_view text) {
    CadTextCheck out;
    const std::vector<Record> records = records_of(text);
    std::vector<const Record*> by_section[5];
    const std::string_view letters = "SGDPT";
    long last_line = 0;
    for (const Record& r : records) {
        const auto s = letters.find(section_of(r));
        if (s != std::string_view::npos) by_section[s].push_back(&r);
        last_line = r.line;
    }
    auto& S = by_section[0];
    auto& G = by_section[1];
    auto& D = by_section[2];
    auto& P = by_section[3];
    auto& T = by_section[4];
    if (G.empty()) {
        out.not_the_format = true;
        out.why_not = S.empty() ? "it has no IGES Start or Global section (80-column records "
                                  "marked S and G in column 73)"
                                : "it has no IGES Global section (records marked G in column 73)";
        return out;
    }
    const std::size_t counted[4] = {S.size(), G.size(), D.size(), P.size()};
    auto counts_text = [&](const long* c) {
        std::string s;
        for (int k = 0; k < 4; ++k)
            s += (k ? ", " : "") + std::string(1, letters[k]) + " " + std::to_string(c[k]);
        return s;
    };
    const long have[4] = {static_cast<long>(counted[0]), static_cast<long>(counted[1]),
                          static_cast<long>(counted[2]), static_cast<long>(counted[3])};
    if (T.empty()) {
        out.notes.push_back(
            {"IGES file", "it ends at line " + std::to_string(last_line) +
                              " without its Terminate section: the file was cut short, and "
                              "what followed is not imported (the file has " +
                              counts_text(have) + " lines)"});
    } else {
        const Record& t = *T.front();
        const long said[4] = {field(t, 2, 7), field(t, 10, 7), field(t, 18, 7), field(t, 26, 7)};
        bool same = true;
        for (int k = 0; k < 4; ++k) same = same && said[k] == have[k];
        if (!same)
            out.notes.push_back(
                {"IGES file", "its Terminate section counts " + counts_text(said) +
                                  " lines, the file has " + counts_text(have) +
                                  ": it was cut or damaged, and what is missing is not imported"});
    }
    if (D.size() % 2 != 0)
        out.notes.push_back({"IGES file", "its Directory Entry section has an odd number of "
                                          "lines: the last entity is cut in half"});

    std::string global;
    for (const Record* r : G) global.append(r->text.substr(0, 72));
    std::unordered_map<long, std::string> data_of;
    for (const Record* r : P)
        if (const long de = field(*r, 66, 7); de > 0) data_of[de].append(r->text.substr(0, 64));
    const auto [param, record] = delimiters(global);
    for (std::size_t k = 0; k + 1 < D.size(); k += 2) {
        const Record& d1 = *D[k];
        const long type = field(d1, 1, 8);
        if (type != 126 && type != 128) continue;
        const int de_line = static_cast<int>(k + 1);
        // Parameter data records carry their entity's DE number (columns 66-72), and readers
        // gather an entity's data by it (the DE's pointer and line count are only a hint).
        const long sequence = field(d1, 74, 7);
        const auto found = data_of.find(sequence > 0 ? sequence : de_line);
        if (found == data_of.end()) {
            out.bad_entities.push_back({de_line, "it has no parameter data in the file"});
            continue;
        }
        const std::string& data = found->second;
        check_bspline_entity(static_cast<int>(type), de_line, data, param, record,
                             out.bad_entities);
    }
    return out;
}

// ---------------------------------------------------------------------------------------
// STEP (ISO 10303-21): "ISO-10303-21;" first (after comments and blanks), a HEADER and a
// DATA section, each ending with "ENDSEC;", and "END-ISO-10303-21;" last.

std::string_view skip_blanks_and_comments(std::string_view t) {
    while (true) {
        while (!t.empty() && (t.front() == ' ' || t.front() == '\t' || t.front() == '\r' ||
                              t.front() == '\n' || t.front() == '\f'))
            t.remove_prefix(1);
        if (t.substr(0, 2) != "/*") return t;
        const auto end = t.find("*/", 2);
        if (end == std::string_view::npos) return {};
        t.remove_prefix(end + 2);
    }
}

CadTextCheck check_step(std::string_view text) {
    CadTextCheck out;
    const std::string_view start = skip_blanks_and_comments(text);
    if (start.substr(0, 13) != "ISO-10303-21;") {
        out.not_the_format = true;
        out.why_not = "it does not begin with ISO-10303-21; (the STEP exchange structure's "
                      "first keyword)";
        return out;
    }
    // The end keyword, outside any string: the last non-blank text of the file.
    std::string_view tail = text;
    while (!tail.empty() && (tail.back() == ' ' || tail.back() == '\t' || tail.back() == '\r' ||
                             tail.back() == '\n' || tail.back() == '\f' || tail.back() == '\0'))
        tail.remove_suffix(1);
    const std::string_view end_keyword = "END-ISO-10303-21;";
    if (tail.size() < end_keyword.size() ||
        tail.substr(tail.size() - end_keyword.size()) != end_keyword) {
        long lines = static_cast<long>(std::count(text.begin(), text.end(), '\n')) + 1;
        out.step_cut_short = true;
        out.notes.push_back({"STEP file", "it ends at line " + std::to_string(lines) +
                                              " without END-ISO-10303-21;: the file was cut "
                                              "short; the entities before the cut are read, "
                                              "what followed is lost"});
    }
    return out;
}

} // namespace

std::string step_completed(std::string_view text) {
    const auto data = text.rfind("DATA;");
    if (data == std::string_view::npos) return std::string(text);
    if (text.find("ENDSEC;", data) != std::string_view::npos)
        return std::string(text) + "\nEND-ISO-10303-21;\n";
    const auto last = text.rfind(';');
    if (last == std::string_view::npos || last < data) return std::string(text);
    std::string out(text.substr(0, last + 1));
    out += "\nENDSEC;\nEND-ISO-10303-21;\n";
    return out;
}

namespace {} // namespace

std::string iges_without_entities(std::string_view text, const std::vector<BadEntity>& bad) {
    std::string out(text);
    std::vector<const Record*> directory;
    const std::vector<Record> records = records_of(text);
    for (const Record& r : records)
        if (section_of(r) == 'D') directory.push_back(&r);
    for (const BadEntity& b : bad) {
        const auto first = static_cast<std::size_t>(b.directory_line - 1);
        for (std::size_t k = first; k < first + 2 && k < directory.size(); ++k) {
            const auto at = static_cast<std::size_t>(directory[k]->text.data() - text.data());
            out.replace(at, 8, "       0");
        }
    }
    return out;
}

CadTextCheck check_cad_text(std::string_view text, CadFormat format) {
    return format == CadFormat::iges ? check_iges(text) : check_step(text);
}

} // namespace isoparm::exchange
