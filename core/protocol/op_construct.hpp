// The construction ops of the geom protocol (make_compatible, ruled, revolve, swing, sweep,
// skin, coons, gordon): one handler each, registered in protocol.cpp's op table.
#pragma once

#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

OpResult op_make_compatible(const json& request); // op_construct.cpp
OpResult op_ruled(const json& request);
OpResult op_revolve(const json& request);
OpResult op_swing(const json& request);
OpResult op_sweep(const json& request);
OpResult op_skin(const json& request);
OpResult op_coons(const json& request);
OpResult op_gordon(const json& request);

} // namespace isoparm::protocol
