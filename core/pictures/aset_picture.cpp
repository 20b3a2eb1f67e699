#include "pictures/aset_picture.h"

#include "util/number_text.h"

namespace facetlight {
namespace {

constexpr int kTitleHeight = 34;
constexpr int kLegendRow = 22;
const Rgb kBackground{0.62f, 0.62f, 0.62f};  // off the stone: a grey apart from every class colour
const Rgb kInk{0.1f, 0.1f, 0.1f};

std::string percent(const AsetShare& s) {
    return formatNumber("%5.1f%%", 100 * s.share) + formatNumber(" +- %.2f", 100 * s.standardError);
}

std::string degreesText(double d) {
    return formatNumber("%g", d);
}

}  // namespace

Rgb asetColour(AsetClass c, const AsetSettings& settings) {
    switch (c) {
        case AsetClass::Head:
            return {0.12f, 0.25f, 0.95f};
        case AsetClass::Bright:
            return {0.92f, 0.1f, 0.08f};
        case AsetClass::Low:
            return {0.1f, 0.78f, 0.15f};
        case AsetClass::Leakage:
            return settings.whiteLeakage ? Rgb{1, 1, 1} : Rgb{0, 0, 0};
        case AsetClass::Trapped:
            return {0.55f, 0.3f, 0.55f};
    }
    return {};
}

Image asetPicture(const AsetView& view, const AsetSettings& settings, const std::string& title) {
    const int legendHeight = kAsetClasses * kLegendRow + 10;
    const int width = std::max(view.width, 640);
    Image image(width, kTitleHeight + view.height + legendHeight, {1, 1, 1});
    const int left = (width - view.width) / 2;
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            const auto& counts = view.counts[size_t(y) * view.width + x];
            Rgb sum;
            int stone = 0;
            for (int c = 0; c < kAsetClasses; ++c) {
                const Rgb colour = asetColour(AsetClass(c), settings);
                sum.r += counts[c] * colour.r;
                sum.g += counts[c] * colour.g;
                sum.b += counts[c] * colour.b;
                stone += counts[c];
            }
            // Rays that missed the stone show the background, so the outline is anti-aliased.
            const float off = float(view.samples - stone);
            const float scale = 1.0f / float(view.samples);
            image.at(left + x, kTitleHeight + y) = {(sum.r + off * kBackground.r) * scale,
                                                    (sum.g + off * kBackground.g) * scale,
                                                    (sum.b + off * kBackground.b) * scale};
        }
    }
    drawText(image, width / 2.0, 8, title, textWidth(title, 2) > width - 10 ? 1.5 : 2, kInk, Align::Center);

    const std::string head = degreesText(settings.headConeDeg), low = degreesText(settings.lowBelowDeg);
    const std::string top = degreesText(90 - settings.headConeDeg);
    const char* labels[kAsetClasses] = {"head", "bright", "low", "leakage", "trapped"};
    const std::string angles[kAsetClasses] = {
        "within " + head + " deg of the viewer",
        low + "-" + top + " deg elevation",
        "0-" + low + " deg elevation",
        "below the horizon",
        "bounce limit",
    };
    const double y0 = kTitleHeight + view.height + 8;
    for (int c = 0; c < kAsetClasses; ++c) {
        const double y = y0 + c * kLegendRow;
        const Point2 box[4] = {Point2{10, y}, Point2{26, y}, Point2{26, y + 16}, Point2{10, y + 16}};
        fillPolygon(image, box, asetColour(AsetClass(c), settings));
        drawPolyline(image, box, true, 1, kInk);
        drawText(image, 34, y + 1, std::string(labels[c]) + ": " + angles[c], 2, kInk);
        drawText(image, width - 10, y + 1, percent(view.share(AsetClass(c))), 2, kInk, Align::Right);
    }
    return image;
}

}  // namespace facetlight
