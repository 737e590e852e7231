// The sim's view of the sea model (model/): the scene as it is, and the model's formulas in the
// libm arithmetic the sim has always evaluated them in (model/arithmetic.hpp says why not the
// codec's). The one place the sim chooses its arithmetic.
#pragma once

#include "arithmetic.hpp"
#include "dispersion.hpp"
#include "initial_amplitude.hpp"
#include "param_message.hpp"
#include "scene_params.hpp"
#include "spectrum.hpp"

#include <complex>

namespace ocean::sim {

using model::bad_param;
using model::format_value;
using model::initial_amplitude;  // deduces the sim's arithmetic from its Spectrum
using model::ParamError;
using model::power_of_two_in;
using model::SceneParams;
using model::wavenumber;

using Spectrum = model::Spectrum<model::Libm>;

inline double angular_frequency(double k, double gravity, double depth_m) {
  return model::angular_frequency<model::Libm>(k, gravity, depth_m);
}


}  // namespace ocean::sim
