#pragma once
// A stored photon, packed into 20 bytes (after Jensen's 20-byte photon): millions of them must stay in cache
// as long as possible while the photon map is gathered.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry/geometry.h"

namespace facetlight {

struct Photon {
    float position[3];
    float power;                 // watts, or any unit the map's user keeps consistent
    uint16_t direction;          // direction of travel on arrival, octahedral 8 + 8 bits
    uint16_t wavelengthAndAxis;  // bits 0-13: wavelength in 0.1 nm (0: none); bits 14-15: kd-tree split axis

    static constexpr double kWavelengthStep = 0.1;  // nm
    static constexpr double kMaxWavelength = 0x3fff * kWavelengthStep;

    // `travel` need not be normalised but must be non-zero; a wavelength of 0 marks a non-spectral photon.
    static Photon make(const Vec3& position, float power, const Vec3& travel, double wavelengthNm = 0);

    Vec3 pos() const { return {position[0], position[1], position[2]}; }
    Vec3 travel() const;  // unit direction of travel, within about 1 degree of the stored one
    double wavelength() const { return (wavelengthAndAxis & 0x3fff) * kWavelengthStep; }
    int axis() const { return wavelengthAndAxis >> 14; }
    void setAxis(int a) { wavelengthAndAxis = uint16_t((wavelengthAndAxis & 0x3fff) | (a << 14)); }
};
static_assert(sizeof(Photon) == 20, "the photon map's memory and cache budget assume 20-byte photons");

// Octahedral mapping (Meyer et al., "On floating-point normal vectors", 2010) of a unit vector to 2 x 8 bits.
inline uint16_t encodeDirection(const Vec3& d) {
    const double l1 = std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    double u = d.x / l1, v = d.y / l1;
    if (d.z < 0) {
        const double fu = (1 - std::fabs(v)) * (u < 0 ? -1 : 1);
        v = (1 - std::fabs(u)) * (v < 0 ? -1 : 1);
        u = fu;
    }
    auto quantise = [](double x) { return uint16_t(std::clamp(std::lround((x + 1) * 127.5), 0L, 255L)); };
    return uint16_t(quantise(u) | (quantise(v) << 8));
}

inline Vec3 decodeDirection(uint16_t code) {
    const double u = (code & 0xff) / 127.5 - 1, v = (code >> 8) / 127.5 - 1;
    const double z = 1 - std::fabs(u) - std::fabs(v);
    Vec3 d{u, v, z};
    if (z < 0) d = {(1 - std::fabs(v)) * (u < 0 ? -1 : 1), (1 - std::fabs(u)) * (v < 0 ? -1 : 1), z};
    return normalize(d);
}

inline Photon Photon::make(const Vec3& p, float power, const Vec3& travel, double wavelengthNm) {
    Photon ph;
    ph.position[0] = float(p.x);
    ph.position[1] = float(p.y);
    ph.position[2] = float(p.z);
    ph.power = power;
    ph.direction = encodeDirection(travel);
    const long w = std::lround(std::clamp(wavelengthNm, 0.0, kMaxWavelength) / kWavelengthStep);
    ph.wavelengthAndAxis = uint16_t(w);
    return ph;
}

inline Vec3 Photon::travel() const {
    return decodeDirection(direction);
}

}  // namespace facetlight
