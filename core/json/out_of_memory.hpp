// Out of memory as an error, not an abort.
//
// Why a plain `catch (std::bad_alloc&)` is not enough: nlohmann::json's destructor flattens a
// tree into a heap-allocated std::vector before freeing it (json_value::destroy), so the
// destructor itself allocates. When the first std::bad_alloc unwinds through a big tree (the
// request being parsed, the answer being built), that allocation fails too, inside a noexcept
// destructor, and std::terminate follows (SIGABRT). Two things prevent it:
// - a reserve of address space held while work runs: the first allocation that fails releases
//   it and then throws, so the destructors running during the unwinding find memory again;
// - release_json, which empties a tree from its leaves up without allocating anything, for the
//   trees whose size follows the input (the parsed request), which no fixed reserve can cover.
// The work budget (work_budget.hpp) keeps answers small enough for the reserve.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>

namespace isoparm::json_io {

// Sets aside `bytes` of address space (never touched, so it costs no physical memory) and
// installs the new-handler that gives it back on the first failed allocation and throws
// std::bad_alloc. Call again after catching std::bad_alloc to set a new reserve aside. Where
// `bytes` cannot be had, smaller amounts are tried (down to 1 MiB).
std::size_t default_memory_reserve_bytes();
void arm_memory_reserve(std::size_t bytes = default_memory_reserve_bytes());

// Whether a reserve is currently set aside (false after it was spent, until re-armed).
bool memory_reserve_armed();

// Empties `value` (children before parents, recursion as deep as the tree, which the reader
// caps at 256 levels) without allocating, so destroying it afterwards cannot allocate either.
void release_json(nlohmann::json& value) noexcept;

// Releases a tree when it goes out of scope, also during unwinding: declare it after the tree.
class ReleaseJsonOnExit {
public:
    explicit ReleaseJsonOnExit(nlohmann::json& value) : value_(value) {}
    ReleaseJsonOnExit(const ReleaseJsonOnExit&) = delete;
    ReleaseJsonOnExit& operator=(const ReleaseJsonOnExit&) = delete;
    ~ReleaseJsonOnExit() { release_json(value_); }

private:
    nlohmann::json& value_;
};

// The one sentence every boundary uses for running out of memory.
inline constexpr const char* out_of_memory_message =
    "not enough memory: the request needs more memory than is available";

} // namespace isoparm::json_io
