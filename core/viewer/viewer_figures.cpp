#include "viewer/viewer_figures.h"

#include <algorithm>
#include <cmath>

#include "scene/scene.h"
#include "trace/trace_base.h"

namespace facetlight {
namespace {

ViewerFigure share(uint64_t count, uint64_t n) {
    if (n == 0) return {};
    const double p = double(count) / double(n);
    return {p, std::sqrt(p * (1 - p) / double(n))};
}

// The ratio estimate total / rays; its error from the spread of the points' own means (a point's looks are
// not independent of one another).
ViewerFigure pointMean(double total, uint64_t rays, const PointMean& m, uint64_t points) {
    if (rays == 0 || points == 0) return {};
    const double mean = double(m.sum) / kViewerScale / double(points);
    const double meanSquare = double(m.squareSum) / kViewerScale / double(points);
    return {total / double(rays), std::sqrt(std::max(0.0, meanSquare - mean * mean) / double(points))};
}

// The dark share of the profile's slices [first, last] and [bins - 1 - last, bins - 1 - first] (mirrored).
ViewerFigure profileDark(const OfficeTally& t, int first, int last) {
    uint64_t rays = 0, dark = 0;
    for (int b = first; b <= last; ++b)
        for (const int k : {b, OfficeTally::kProfileBins - 1 - b}) {
            rays += t.profileRays[size_t(k)];
            dark += t.profileDark[size_t(k)];
        }
    return share(dark, rays);
}

}  // namespace

ViewerFigure ViewerFigures::brightness() const {
    return pointMean(double(office.radiance) / kViewerScale, office.rays, office.brightness, office.points);
}
ViewerFigure ViewerFigures::fire() const {
    return share(spot.coloured, spot.hit);
}
ViewerFigure ViewerFigures::scintillation() const {
    return share(office.switched, office.pairs);
}
ViewerFigure ViewerFigures::contrast() const {
    return pointMean(double(office.viewer), office.rays, office.contrast, office.points);
}
ViewerFigure ViewerFigures::windowing() const {
    return pointMean(double(office.background), office.rays, office.windowing, office.points);
}
ViewerFigure ViewerFigures::extinction() const {
    return share(office.darkRocks, office.rocks);
}
ViewerFigure ViewerFigures::girdleInTable() const {
    return share(office.tableGirdle, office.tableRays);
}
ViewerFigure ViewerFigures::seeThroughTable() const {
    return share(office.tableThrough, office.tableRays);
}
ViewerFigure ViewerFigures::headInTableCentre() const {
    return share(office.centreHead, office.centreRays);
}
ViewerFigure ViewerFigures::darkMiddle() const {
    // The middle: |x| within 1/16 of the length; either side: from 1/8 to 1/4 of the length out.
    constexpr int n = OfficeTally::kProfileBins;
    const ViewerFigure middle = profileDark(office, n / 2 - 1, n / 2 - 1);
    const ViewerFigure sides = profileDark(office, n / 4, n / 4 + 1);
    return {middle.value - sides.value, std::hypot(middle.stderr, sides.stderr)};
}

const ViewerFigureInfo* findViewerFigure(std::string_view key) {
    for (const ViewerFigureInfo& f : kViewerFigures)
        if (f.key == key) return &f;
    return nullptr;
}

uint64_t viewerUnits(const ViewerSettings& s) {
    return s.office.points * uint64_t(s.positions()) * 2 + s.spot.photons;
}

ViewerFigures viewStone(const Stone& stone, const TraceSettings& trace, RunControl* control) {
    const ViewerSettings& settings = trace.viewer;
    settings.validate();
    // The set-ups bring their own light: the scene's is a dome, so that nothing takes a collimated beam's
    // short cuts (trace/trace_base.h).
    TraceSettings own = trace;
    own.light = LightSettings{};
    own.light.model = LightModelKind::Hemisphere;
    const Scene scene(stone, own);
    const TraceBase base(scene, own);
    ViewerFigures figures;
    bool finished = false;
    figures.office = officeView(base, settings, control, finished);
    if (finished) figures.spot = spotFire(base, settings, control, finished);
    figures.cancelled = !finished;
    return figures;
}

}  // namespace facetlight
