#include "ui/view/control_net.hpp"

namespace isoparm::ui {

int ControlNet::find(int i, int j) const {
    for (std::size_t k = 0; k < ids.size(); ++k)
        if (ids[k] == std::pair(i, j)) return static_cast<int>(k);
    return -1;
}

} // namespace isoparm::ui
