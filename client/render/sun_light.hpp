// SunLight: the colour of the sunlight that reaches the sea, from the sun's elevation. A low sun's
// light crosses more air, which scatters the blue out of it first (Rayleigh, 1 / wavelength^4),
// so it reddens and dims toward the horizon; the sky painter's glow and the water's highlight and
// glow through crests take the same colour.
#pragma once

#include <glm/glm.hpp>

namespace ocean::render {

// The sun's colour at kReferenceElevationRad, the default sky's 12 degrees: (2.6, 2.35, 1.9), > 1
// so that its glitter saturates.
inline constexpr float kReferenceElevationRad = 0.20944f;
inline constexpr glm::vec3 kReferenceSunColour{2.6f, 2.35f, 1.9f};

// Air masses the light crosses at an elevation, 1 at the zenith (Kasten and Young 1989); the
// elevation is taken at 0 below the horizon.
float air_mass(float elevation_rad);

// What a clear atmosphere lets through per channel (red 680, green 550, blue 450 nm): exp(-tau
// m), with optical depths in Rayleigh's ratios, scaled so that the reference colour above is the
// default sky's.
glm::vec3 transmittance(float elevation_rad);

// The sunlight at an elevation: the reference colour times the transmittance relative to the
// reference elevation's, fading to 0 as the disc sets (1 degree above the horizon to 1 below).
glm::vec3 sunlight(float elevation_rad);

}  // namespace ocean::render
