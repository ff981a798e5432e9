// The memory reserve and allocation-free release of JSON trees (see out_of_memory.hpp).
#include "core/json/out_of_memory.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

namespace isoparm::json_io {

namespace {

std::atomic<void*> reserve{nullptr};

// Called by operator new when malloc fails. Give the reserve back and fail this allocation:
// the work stops (std::bad_alloc), and the destructors run during the unwinding have the
// reserve's memory to use. Without a reserve, fail as if no handler were installed.
void release_reserve_and_fail() {
    if (void* r = reserve.exchange(nullptr)) std::free(r);
    throw std::bad_alloc();
}

} // namespace

std::size_t default_memory_reserve_bytes() {
    // Covers the unwinding of any answer within the work budget: nlohmann's destructor needs
    // 16 bytes per element of the widest array (a 1,000,000-vertex mesh: 16 MB, twice that
    // while its vector grows).
    return std::size_t{96} << 20;
}

void arm_memory_reserve(std::size_t bytes) {
    std::set_new_handler(release_reserve_and_fail);
    if (reserve.load() != nullptr) return;
    for (; bytes >= (std::size_t{1} << 20); bytes /= 2) {
        // malloc, not new: the handler above must not run for the reserve itself. The memory
        // is never written, so only address space is taken.
        if (void* r = std::malloc(bytes)) {
            void* expected = nullptr;
            if (!reserve.compare_exchange_strong(expected, r)) std::free(r);
            return;
        }
    }
}

bool memory_reserve_armed() {
    return reserve.load() != nullptr;
}

void release_json(nlohmann::json& value) noexcept {
    if (value.is_array()) {
        // Last to first: pop_back never reallocates, and each element is a leaf or an empty
        // container by the time it is destroyed.
        auto& items = value.get_ref<nlohmann::json::array_t&>();
        while (!items.empty()) {
            release_json(items.back());
            items.pop_back();
        }
    } else if (value.is_object()) {
        auto& members = value.get_ref<nlohmann::json::object_t&>();
        for (auto& member : members) release_json(member.second);
        members.clear();
    }
}

} // namespace isoparm::json_io
