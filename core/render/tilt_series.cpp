#include "render/tilt_series.h"

#include <cmath>
#include <cstdio>

namespace facetlight {

AsetShare TiltSeries::scintillation() const {
    if (pixelPairs == 0) return {};
    const double p = double(switched) / double(pixelPairs);
    return {p, std::sqrt(p * (1 - p) / double(pixelPairs))};
}

TiltSeries tiltSeries(const TraceBase& trace, const CameraSettings& camera, int width, int height,
                      const AsetSettings& aset, const TiltSeriesSettings& settings, RunControl* control) {
    settings.validate();
    const TraceSettings& job = trace.settings();
    TiltSeries series;
    series.axisDeg = settings.axisDeg;
    for (int k = 0; k < settings.frames(); ++k) {
        const StoneTurn turn{settings.tiltDeg(k), settings.axisDeg};
        TiltFrame frame{settings.tiltDeg(k),
                        asetView(trace, camera, width, height, aset, job.threads, job.seed, control, turn),
                        {}};
        if (frame.view.cancelled) {
            series.cancelled = true;
            return series;
        }
        const AsetShare bright = frame.view.share(AsetClass::Bright), low = frame.view.share(AsetClass::Low);
        const double p = bright.share + low.share, n = double(frame.view.stoneRays());
        frame.lightReturn = {p, n > 0 ? std::sqrt(p * (1 - p) / n) : 0};
        if (!series.frames.empty()) {
            const AsetView& before = series.frames.back().view;
            for (size_t i = 0; i < before.counts.size(); ++i) {
                if (!before.onStone(i) || !frame.view.onStone(i)) continue;
                ++series.pixelPairs;
                series.switched += before.lit(i) != frame.view.lit(i);
            }
        }
        series.frames.push_back(std::move(frame));
    }
    return series;
}

std::string tiltAxisName(double axisDeg) {
    if (axisDeg == 0) return "x";
    if (axisDeg == 90) return "y";
    char name[48];
    std::snprintf(name, sizeof name, "the axis at %g deg azimuth", axisDeg);
    return name;
}

nlohmann::json toJson(const TiltSeries& series, const TiltSeriesSettings& settings) {
    nlohmann::json frames = nlohmann::json::array();
    for (const TiltFrame& f : series.frames) {
        nlohmann::json shares = nlohmann::json::object();
        for (int c = 0; c < kAsetClasses; ++c) {
            shares[std::string(asetClassName(AsetClass(c)))] = f.view.share(AsetClass(c)).share;
        }
        frames.push_back({{"tilt_deg", f.tiltDeg},
                          {"light_return", f.lightReturn.share},
                          {"light_return_stderr", f.lightReturn.standardError},
                          {"shares", shares}});
    }
    const AsetShare s = series.scintillation();
    return {{"settings", toJson(settings)},
            {"frames", frames},
            {"scintillation", s.share},
            {"scintillation_stderr", s.standardError},
            {"pixel_pairs", series.pixelPairs}};
}

}  // namespace facetlight
