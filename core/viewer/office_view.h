#pragma once
// The office set-up traced from the viewer's eye (docs/physics.md, "Viewer figures"): face-up points of the
// stone, each seen through the pupil from every position of the motion, each view ray followed back through
// the stone (PhotonWalker::view) to what it meets: the dome, the viewer, the tray below, or nothing
// (trapped). Point j draws from Rng(seed, j) alone and takes the same draws at every position, so a point
// whose light path does not change with the motion keeps what it sees: switching measures the stone, not the
// noise. The tallies are integers: the same bits for any thread count.
#include <array>
#include <cstdint>
#include <vector>

#include "optics/observer.h"
#include "optics/viewer_settings.h"
#include "trace/trace_base.h"
#include "util/run_control.h"

namespace facetlight {

// Fixed point of radiances and per-point means: 2^24 per unit.
constexpr double kViewerScale = 16777216.0;

// A mean over points, each point's own mean kept for the standard error (in kViewerScale fixed point).
struct PointMean {
    uint64_t sum = 0, squareSum = 0;  // of the points' means, and of their squares
    void add(double pointMean);
    void merge(const PointMean& o) {
        sum += o.sum;
        squareSum += o.squareSum;
    }
    bool operator==(const PointMean&) const = default;
};

struct OfficeTally {
    uint64_t points = 0;    // face-up points that met the stone in at least one position
    uint64_t rays = 0;      // view rays that met the stone, over all points and positions
    uint64_t radiance = 0;  // their radiance, fixed point
    uint64_t sky = 0, viewer = 0, background = 0, trapped = 0;  // what they met
    PointMean brightness, contrast, windowing;  // per point: mean radiance, share of viewer, of background
    // Looks a sparkle step apart both on the stone, and those between which the point switched between lit
    // (the dome) and dark (anything else).
    uint64_t pairs = 0, switched = 0;
    // Rocks (every look at one turn) of a point on the stone throughout, and those dark throughout.
    uint64_t rocks = 0, darkRocks = 0;
    // Face-up (the tilt nearest 0), every turn: rays in through the table, those of them whose path met the
    // girdle (fish-eye), those dark and those that see the tray through the stone; rays at the table's centre
    // (within half its radius), those dark there and those that see the viewer's head (nail-head); and rays
    // and dark rays in kProfileBins slices across the stone's length (x), for the bow-tie.
    uint64_t tableRays = 0, tableGirdle = 0, tableDark = 0, tableThrough = 0;
    uint64_t centreRays = 0, centreDark = 0, centreHead = 0;
    static constexpr int kProfileBins = 16;
    std::array<uint64_t, kProfileBins> profileRays{}, profileDark{};

    void merge(const OfficeTally& o);
    bool operator==(const OfficeTally&) const = default;
};

// Traces `settings.office.points` points of the trace's stone at its size (`size_mm`), with its seed, threads
// and bounce limit; the scene's light plays no part. Advances control->done() by the view rays of each block
// of points. `finished`: whether it ran to the end.
OfficeTally officeView(const TraceBase& trace, const ViewerSettings& settings, RunControl* control,
                       bool& finished);

// The face-up stone as the viewer's eye sees it in the office at one position: `size` x `size` pixels over
// the square around the stone's widest circle (+y up, the viewer's side at the bottom), each pixel the mean
// of `samples` view rays through the pupil's centre, jittered in the pixel. Pixel p's ray s draws from
// Rng(seed, p * samples + s): the same bits for any thread count.
struct OfficeImage {
    int size = 0;
    std::vector<float> radiance;  // per pixel, row by row from the top; -1 off the stone
    std::vector<Seen> seen;       // per pixel: what most of its rays met
};
OfficeImage officeImage(const TraceBase& trace, const ViewerSettings& settings, int size, int samples,
                        double tiltDeg, double turnDeg, RunControl* control = nullptr);

}  // namespace facetlight
