// A scratch array on the stack for the usual small sizes, on the heap beyond: evaluation at a
// single point must not allocate for degrees up to 15.
#pragma once

#include <cstddef>
#include <memory>

namespace isoparm::geom {

template <class T, std::size_t Inline> class SmallBuffer {
public:
    explicit SmallBuffer(std::size_t n) {
        if (n > Inline) {
            heap_ = std::make_unique<T[]>(n);
            data_ = heap_.get();
        }
    }
    SmallBuffer(const SmallBuffer&) = delete;
    SmallBuffer& operator=(const SmallBuffer&) = delete;
    T* data() { return data_; }
    T& operator[](std::size_t k) { return data_[k]; }

private:
    T local_[Inline];
    std::unique_ptr<T[]> heap_;
    T* data_ = local_;
};

} // namespace isoparm::geom
