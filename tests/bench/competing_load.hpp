// A competing load for the thread benchmarks: busy-spinning child processes, as many as asked
// (typically one per core), not pinned (the scheduler places them as it would any other
// program's), stopped when the object ends. What "other processes compete" means in the
// figures the benchmarks print under load.
#pragma once

#include <vector>

namespace isoparm::bench {

class CompetingLoad {
public:
    // Starts `processes` spinning children (none where the system has no fork: running() says).
    explicit CompetingLoad(int processes);
    ~CompetingLoad(); // kills and reaps its children, by their process ids
    CompetingLoad(const CompetingLoad&) = delete;
    CompetingLoad& operator=(const CompetingLoad&) = delete;

    int running() const { return static_cast<int>(pids_.size()); }

private:
    std::vector<int> pids_;
};

// The cores this process may run on (at least 1).
int available_cores();

} // namespace isoparm::bench
