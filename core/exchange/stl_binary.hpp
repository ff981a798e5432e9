// Binary STL: an 80-byte header, a little-endian uint32 triangle count, then 50 bytes per
// triangle (normal and three vertices as little-endian IEEE 754 binary32, a uint16 attribute
// byte count of 0). The de-facto format of 3D printing (3D Systems' StereoLithography
// Interface Specification, 1989/1991).
#pragma once

#include <string>
#include <vector>

#include "core/geom/tessellate.hpp"

namespace isoparm::exchange {

// The file's bytes. The header says "isoparm binary STL: <name>" (cut to 80 bytes, padded with
// spaces) and never starts with "solid", which some readers take as the sign of ASCII STL.
// Each facet's normal is its unit geometric normal (b - a) x (c - a), zero for a zero-area
// triangle; coordinates are rounded to the nearest binary32 (the format has no other).
std::string stl_binary_bytes(const std::vector<geom::Mesh>& meshes, const std::string& name);

} // namespace isoparm::exchange
