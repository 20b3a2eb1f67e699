#include "trace/fire_trace.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "trace/photon_walker.h"

namespace facetlight {
namespace {

using BandExit = PhotonWalker::BandExit;

// The fire tallies of photons whose bands have been walked.
class FireTally {
  public:
    FireTally(const TraceBase& t, FireStats& stats)
        : t_(t),
          st_(stats),
          up_(t.scene().up()),
          cosHeadCone_(t.scene().lightSettings().headShadowDeg > 0
                           ? std::cos(radians(t.scene().lightSettings().headShadowDeg))
                           : 2.0),
          pupil_(uint64_t(t.settings().fire.pupilAngleDeg() * kSeparationScale + 0.5)) {}

    // Tallies one photon, band k of which went as bands[k].
    void add(std::span<const BandExit, kFireBands> bands) {
        ++st_.photons;
        if (bands[0].outcome == PhotonOutcome::Missed) return;  // a miss does not depend on the index
        ++st_.hit;
        std::array<bool, kFireBands> up;
        for (int k = 0; k < kFireBands; ++k) st_.crownReturn[k] += up[k] = upward(bands[k]);
        const BandExit &red = bands[kFireRed], &blue = bands[kFireBlue];
        if (!up[kFireRed] && !up[kFireBlue]) return;
        if (!(up[kFireRed] && up[kFireBlue] && red.path == blue.path)) {
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
        const int exitBin = exitBins_(cosUp);
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
    // Out through table or crown into the upper hemisphere.
    bool upward(const BandExit& b) const {
        return b.outcome == PhotonOutcome::Exited && t_.crownSide(b.facet) && dot(b.dir, Vec3f(up_)) > 0;
    }

    const TraceBase& t_;
    FireStats& st_;
    const Vec3 up_;
    const double cosHeadCone_;  // 2: no cone
    const uint64_t pupil_;      // the pupil's angle, fixed point
    const FireExitBins exitBins_;
};

}  // namespace

std::array<FireBand, kFireBands> fireBands(const Scene& scene) {
    std::array<FireBand, kFireBands> bands;
    for (int k = 0; k < kFireBands; ++k) {
        const double nm = scene.dispersive() ? kFireWavelengthsNm[k] : Material::kSodiumD;
        bands[k] = {float(scene.refractiveIndex(nm)), float(nm)};
    }
    return bands;
}

void traceFire(const TraceBase& trace, uint64_t begin, uint64_t end, FacetStats& plain, FireStats& stats) {
    thread_local std::vector<BandExit> exits;  // the block's, sized once per thread
    exits.resize((end - begin) * kFireBands);
    PhotonWalker::tallyAndBands(trace, begin, end, plain, fireBands(trace.scene()), exits);
    FireTally tally(trace, stats);
    for (size_t i = 0; i < end - begin; ++i)
        tally.add(std::span<const BandExit, kFireBands>(&exits[i * kFireBands], kFireBands));
}

void traceFirePhotonByPhoton(const TraceBase& trace, uint64_t begin, uint64_t end, FireStats& stats) {
    const std::array<FireBand, kFireBands> bands = fireBands(trace.scene());
    FireTally tally(trace, stats);
    std::array<BandExit, kFireBands> exits;
    for (uint64_t i = begin; i < end; ++i) {
        PhotonWalker::walkBands(trace, i, bands, exits);
        tally.add(exits);
    }
}

}  // namespace facetlight
