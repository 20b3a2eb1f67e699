#include "trace/fire_trace.h"

#include <algorithm>
#include <cmath>

#include "trace/detail/photon_walker.h"

namespace facetlight {
namespace {

// The facets a band met, in order, hashed: two bands took the same path when their hashes agree.
uint64_t pathStep(uint64_t path, uint32_t facet) {
    return mix64(path ^ (uint64_t(facet) + 1));
}

// A PhotonWalker visitor: where each band of one photon left the stone, then the photon's fire tallies.
class FireTally {
  public:
    FireTally(const Scene& s, FireStats& stats)
        : s_(s),
          st_(stats),
          up_(s.up()),
          cosHeadCone_(s.settings().light.headShadowDeg > 0
                           ? std::cos(radians(s.settings().light.headShadowDeg))
                           : 2.0),
          pupil_(uint64_t(s.settings().fire.pupilAngleDeg() * kSeparationScale + 0.5)) {}

    void band(size_t k) {
        band_ = k;
        out_[k] = {};
        path_ = 0;
    }
    void missed() { missed_ = true; }
    void reflectedAtEntry(uint32_t, const Vec3f&, const Vec3f&) {}
    void entered(uint32_t facet) { path_ = pathStep(0, facet); }
    void internalReflection(uint32_t facet) { path_ = pathStep(path_, facet); }
    void exited(uint32_t facet, const Vec3f&, const Vec3f& dir, uint32_t) {
        const Region r = s_.stone().facets[facet].region;
        const bool up = (r == Region::Table || r == Region::Crown) && dot(dir, Vec3f(up_)) > 0;
        out_[band_] = {up, pathStep(path_, facet), facet, dir};
    }
    void trapped(uint32_t) {}
    void lost(uint32_t) {}

    // Tallies the photon whose bands were just walked.
    void finish() {
        ++st_.photons;
        if (missed_) {
            missed_ = false;
            return;
        }
        ++st_.hit;
        for (int k = 0; k < kFireBands; ++k) st_.crownReturn[k] += out_[k].up;
        const Exit &red = out_[kFireRed], &blue = out_[kFireBlue];
        if (!red.up && !blue.up) return;
        if (!(red.up && blue.up && red.path == blue.path)) {
            ++st_.split;
            return;
        }
        ++st_.pairs;
        const Vec3 r(red.dir.x, red.dir.y, red.dir.z), b(blue.dir.x, blue.dir.y, blue.dir.z);
        const double separationDeg = degrees(std::atan2(length(cross(r, b)), dot(r, b)));
        const uint64_t sep = uint64_t(separationDeg * kSeparationScale + 0.5);
        st_.separationSum += sep;
        st_.separationSquareSum += (sep * sep) >> 20;
        // The exit angle of the pair: its bisector's angle to the vertical (below 90 degrees: both go up).
        const double cosUp = std::clamp(dot(normalize(r + b), up_), -1.0, 1.0);
        const int exitBin = std::min(kFireExitBins - 1, int(degrees(std::acos(cosUp)) / kFireExitBinDeg));
        const int sepBin = std::min(kFireSeparationBins - 1, int(separationDeg / kFireSeparationBinDeg));
        ++st_.histogram[exitBin][sepBin];
        if (sep <= pupil_) return;
        ++st_.coloured;
        ++st_.colouredByFacet[red.facet];
        if (cosUp >= cosHeadCone_) return;
        const uint64_t w = uint64_t(cosUp * kWeightScale + 0.5);
        st_.colouredWeightSum += w;
        st_.colouredWeightSquareSum += (w * w) >> 30;
    }

  private:
    struct Exit {
        bool up = false;  // through table or crown into the upper hemisphere
        uint64_t path = 0;
        uint32_t facet = 0;
        Vec3f dir;
    };
    const Scene& s_;
    FireStats& st_;
    const Vec3 up_;
    const double cosHeadCone_;  // 2: no cone
    const uint64_t pupil_;      // the pupil's angle, fixed point
    size_t band_ = 0;
    uint64_t path_ = 0;
    bool missed_ = false;
    std::array<Exit, kFireBands> out_{};
};

}  // namespace

void traceFire(const Scene& scene, uint64_t begin, uint64_t end, FireStats& stats) {
    std::array<float, kFireBands> bands;
    for (int k = 0; k < kFireBands; ++k)
        bands[k] = float(scene.index(scene.dispersive() ? kFireWavelengthsNm[k] : Material::kSodiumD));
    FireTally tally(scene, stats);
    for (uint64_t i = begin; i < end; ++i) {
        PhotonWalker::walkBands(scene, i, bands, tally);
        tally.finish();
    }
}

}  // namespace facetlight
