// A combo box over an enumeration's labels (geom::label_of), in its table's order, so that
// the panels and the messages use the same words and a new value appears everywhere at once.
#pragma once

#include <array>
#include <cctype>
#include <cstddef>
#include <imgui.h>
#include <string>

#include "core/geom/enum_names.hpp"

namespace isoparm::ui {

// Items start with a capital where a list shows them alone ("Rational Bezier"), though a
// message says "a rational Bezier" mid-sentence.
enum class ItemCase { as_labelled, capitalized };

// Shows `value`'s label; true when the user picked another value (then stored in `value`).
template <class E>
bool enum_combo(const char* label, E& value, ItemCase item_case = ItemCase::as_labelled) {
    constexpr std::size_t count = enum_names(E{}).size();
    using Items = std::array<std::string, count>;
    // ImGui asks for each item through a plain function pointer: the texts are built once.
    static const std::array<Items, 2> texts = [] {
        std::array<Items, 2> out;
        for (std::size_t k = 0; k < count; ++k) {
            std::string s = geom::label_of(static_cast<E>(k));
            out[0][k] = s;
            if (!s.empty())
                s[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
            out[1][k] = s;
        }
        return out;
    }();
    const Items& shown = texts[item_case == ItemCase::capitalized ? 1 : 0];
    auto item_text = [](void* data, int k, const char** text) {
        *text = static_cast<const Items*>(data)->at(static_cast<std::size_t>(k)).c_str();
        return true;
    };
    int index = static_cast<int>(value);
    if (!ImGui::Combo(label, &index, item_text, const_cast<Items*>(&shown),
                      static_cast<int>(count)) ||
        index == static_cast<int>(value))
        return false;
    value = static_cast<E>(index);
    return true;
}

} // namespace isoparm::ui
