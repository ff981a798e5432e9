// File formats chosen by extension: one table per format enumeration says which extensions
// name which format, and the same table answers the lookup and the messages that list them.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace isoparm::scene {

template <class E> struct ExtensionOf {
    std::string_view extension; // lower case, with its dot
    E format;
};

// The format whose extension `ext` (lower case, with its dot) is; nothing for another.
template <class E, std::size_t N>
std::optional<E> format_by_extension(const ExtensionOf<E> (&table)[N], std::string_view ext) {
    for (const ExtensionOf<E>& e : table)
        if (e.extension == ext) return e.format;
    return std::nullopt;
}

// ".igs/.iges, .stp/.step, .obj": every extension, those of one format joined by '/'.
template <class E, std::size_t N> std::string extensions_text(const ExtensionOf<E> (&table)[N]) {
    std::string out;
    for (std::size_t k = 0; k < N; ++k) {
        if (k > 0) out += table[k].format == table[k - 1].format ? "/" : ", ";
        out += table[k].extension;
    }
    return out;
}

} // namespace isoparm::scene
