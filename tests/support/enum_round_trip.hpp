// The check every enumeration table passes: each name reads back as its value, none twice.
#pragma once

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/geom/enum_names.hpp"

namespace isoparm::test {

// Each value's name parses back to it and no two values share a name.
template <class E> void expect_round_trip() {
    std::set<std::string> seen;
    for (const geom::EnumName<E>& entry : enum_names(E{})) {
        EXPECT_EQ(geom::parse_name<E>(geom::name_of(entry.value)), entry.value) << entry.name;
        EXPECT_TRUE(seen.insert(entry.name).second) << "duplicate name " << entry.name;
    }
    EXPECT_FALSE(geom::parse_name<E>("").has_value());
    EXPECT_FALSE(geom::parse_name<E>("no such name").has_value());
}

} // namespace isoparm::test
