// AdvancedState: a baseline state carried forward as later ticks ask for it. Advancing composes
// exactly (also across a scene change, SceneTimeline::advance), so a delta of tick t + 2 from the
// same baseline costs the steps since t, not its whole lag again. The encoder keeps one per
// baseline it encodes from; a DecodeMemo one per baseline its decoders share.
#pragma once

#include "modal_model.hpp"
#include "scene_timeline.hpp"
#include "tick.hpp"

namespace ocean::codec {

class AdvancedState {
 public:
  // `baseline` (the state of tick `from`) advanced to `to` >= from; starts again from the
  // baseline when `to` is behind what was reached. Valid until the next call.
  const ModalState& advance(const ModalState& baseline, Tick from, Tick to, const SceneTimeline& scenes) {
    if (!started_ || reached_ > to)
      scenes.advance(baseline, from, to, state_);
    else
      scenes.advance(state_, reached_, to);
    started_ = true;
    reached_ = to;
    return state_;
  }

 private:
  bool started_ = false;
  Tick reached_ = 0;
  ModalState state_;
};

}  // namespace ocean::codec
