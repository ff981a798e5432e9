// The kinds' shared pieces: how a kind is named in a sentence, control point names, boxes.
#include "core/doc/kinds/kind_common.hpp"

#include <glm/common.hpp>

#include "core/json/fields.hpp"

namespace isoparm::doc {

namespace {

std::string with_article(const char* noun) {
    const char c = noun[0];
    const bool vowel = c == 'a' || c == 'e' || c == 'i' || c == 'o' || c == 'u';
    return std::string(vowel ? "an " : "a ") + noun;
}

} // namespace

std::string kind_noun(ObjectKind kind) {
    return with_article(geom::label_of(kind));
}

std::string kind_file_noun(ObjectKind kind) {
    return with_article(geom::name_of(kind));
}

namespace detail {

std::optional<Box> box_of(std::span<const glm::dvec3> points) {
    if (points.empty()) return std::nullopt;
    Box box{points[0], points[0]};
    for (const glm::dvec3& p : points) {
        box.lo = glm::min(box.lo, p);
        box.hi = glm::max(box.hi, p);
    }
    return box;
}

geom::Error index_out_of_range(const char* name, int value, int count, const char* path) {
    return geom::make_error(geom::ErrorCode::schema,
                            std::string("control point index ") + name + " = " +
                                std::to_string(value) + " is outside 0.." +
                                std::to_string(count - 1),
                            path);
}

std::string point_label(char letter, int i, int j) {
    std::string s(1, letter);
    if (j < 0) return s + std::to_string(i);
    if (i < 10 && j < 10) return s + std::to_string(i) + std::to_string(j);
    return s + std::to_string(i) + "," + std::to_string(j);
}

std::string indexed_label(char letter, int i, int j) {
    return std::string(1, letter) + std::to_string(i) + (j >= 0 ? "," + std::to_string(j) : "");
}

std::string triangle_point_label(char letter, int n, int i, int j) {
    const int k = n - i - j;
    std::string s(1, letter);
    if (n < 10) return s + std::to_string(i) + std::to_string(j) + std::to_string(k);
    return s + std::to_string(i) + "," + std::to_string(j) + "," + std::to_string(k);
}

geom::Expected<std::pair<int, int>> point_pair_from_json(const nlohmann::json& point,
                                                         const std::string& at, const char* what,
                                                         int max_i, int max_j) {
    if (!point.is_array() || point.size() != 2) return json_io::schema_error(what, at);
    const int most[2] = {max_i, max_j};
    int idx[2] = {-1, -1};
    for (std::size_t k = 0; k < 2; ++k) {
        auto v = json_io::read_integer(point[k], at + "/" + std::to_string(k),
                                       "a control point index", 0, most[k]);
        if (!v) return v.error();
        idx[k] = static_cast<int>(*v);
    }
    return std::pair{idx[0], idx[1]};
}

} // namespace detail

} // namespace isoparm::doc
