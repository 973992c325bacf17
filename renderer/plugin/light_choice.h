#pragma once
// LightChoice: a light with the probability that next-event estimation chooses it, as the scene fixes it once from
// the lights' powers. Emitters found by rays carry it too, so that their MIS weight needs no lookup.

namespace isotrace {

class Light;

struct LightChoice {
    const Light* light = nullptr;
    float probability = 0;
};

}  // namespace isotrace
