// What holds of the document now, each as a sentence and the expectation that checks it: the
// list a lesson's author picks from (Lessons > Add expectation) while recording. Every fact
// holds when it is made (unmet_expectations answers nothing for it).
#pragma once

#include <string>
#include <vector>

#include "core/doc/document.hpp"
#include "core/scene/expect.hpp"

namespace isoparm::scene {

struct Fact {
    std::string text; // "the weight of P2,2 of 'hill' is 0.3"
    ExpectStep expect;
};

// The number of objects; for the selected object (or, with none selected, the first surface
// or curve): its kind, type, degrees, knots, the selected control point's position and weight,
// and at the indicator its point, the sum of its basis functions, the selected point's basis
// function and the curvatures; each patch group's borders (the strongest of C1 and C0 that
// holds).
std::vector<Fact> document_facts(const doc::Document& d);

} // namespace isoparm::scene
