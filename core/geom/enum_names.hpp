// Names of enumerations, from one table per enumeration: the same table writes a value (scene
// files, protocol answers, messages, menus) and reads it back, so the two cannot drift apart.
//
// Beside each enumeration E stands its table and a function `enum_names(E)` returning it, found
// by argument-dependent lookup; the templates below work on any such E:
//
//   inline constexpr EnumName<Dir> dir_names[] = {{Dir::u, "u"}, {Dir::v, "v"}};
//   static_assert(in_declaration_order(dir_names));
//   constexpr std::span<const EnumName<Dir>> enum_names(Dir) { return dir_names; }
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace isoparm::geom {

template <class E> struct EnumName {
    E value;
    const char* name;            // as files, requests and answers spell it
    const char* label = nullptr; // as menus and messages say it, where that differs
};

// Every table lists the values in declaration order (0, 1, 2, ...), so a value's entry is at
// its own index.
template <class E, std::size_t N>
constexpr bool in_declaration_order(const EnumName<E> (&table)[N]) {
    for (std::size_t k = 0; k < N; ++k)
        if (static_cast<std::size_t>(table[k].value) != k) return false;
    return true;
}

// The name of `value` as files spell it; "?" for a number outside the enumeration.
template <class E> const char* name_of(E value) {
    const std::span<const EnumName<E>> table = enum_names(E{});
    const auto k = static_cast<std::size_t>(value);
    return k < table.size() ? table[k].name : "?";
}

// The name people read: the table's label, or the name where it has none.
template <class E> const char* label_of(E value) {
    const std::span<const EnumName<E>> table = enum_names(E{});
    const auto k = static_cast<std::size_t>(value);
    if (k >= table.size()) return "?";
    return table[k].label ? table[k].label : table[k].name;
}

// The value whose name is `name` (exactly, case included); nothing for any other text.
template <class E> std::optional<E> parse_name(std::string_view name) {
    for (const EnumName<E>& entry : enum_names(E{}))
        if (name == entry.name) return entry.value;
    return std::nullopt;
}

// Every name of the table, for a refusal that lists them: "xy, xz, yz or free3d".
template <class E> std::string names_list(std::string_view last_joint = " or ") {
    const std::span<const EnumName<E>> table = enum_names(E{});
    std::string out;
    for (std::size_t k = 0; k < table.size(); ++k) {
        if (k > 0) out += k + 1 == table.size() ? std::string(last_joint) : std::string(", ");
        out += table[k].name;
    }
    return out;
}

} // namespace isoparm::geom
