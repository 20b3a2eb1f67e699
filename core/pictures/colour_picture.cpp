#include "pictures/colour_picture.h"

#include <algorithm>

#include "util/number_text.h"

namespace facetlight {
namespace {

constexpr int kTitleHeight = 52;
constexpr int kLegendRow = 20;
const Rgb kInk{0.1f, 0.1f, 0.1f};
// Off the stone: a neutral mid grey (L* 50), against which a colour is neither lifted nor dulled.
constexpr double kBackgroundY = 0.1842;

std::string figure(const char* name, const ColourFigure& f) {
    return std::string(name) + " " + formatNumber("%.1f", f.mean) + " +- " +
           formatNumber("%.2f", f.meanError) + " (spread " + formatNumber("%.1f", f.spread) + ")";
}

std::string percent(const char* name, const ColourShare& s) {
    return std::string(name) + " " + formatNumber("%.1f", 100 * s.share) + " +- " +
           formatNumber("%.1f", 100 * s.standardError) + " %";
}

// A legend line at (x, y), as large as fits the picture's width.
void legendText(Image& image, double x, double y, const std::string& text) {
    drawText(image, x, y, text, std::min(1.5, (image.width() - 5 - x) / std::max(1.0, textWidth(text, 1))),
             kInk);
}

Rgb display(const Vec3& xyz) {
    const Vec3 rgb = xyzToLinearSrgb(xyz);
    return {float(srgbEncode(rgb.x)), float(srgbEncode(rgb.y)), float(srgbEncode(rgb.z))};
}

}  // namespace

std::string colourTitle(const std::string& stoneName, const TraceSettings& settings) {
    return "True colour face-up: " + stoneName + ", " + settings.material + ", " +
           formatNumber("%g", settings.sizeMm) + " mm";
}

std::string colourSummary(const ColourView& v) {
    return figure("L*", v.L) + ", " + figure("a*", v.a) + ", " + figure("b*", v.b) + ", " +
           figure("C*ab", v.chroma) + "; " + percent("windowed", v.windowed) + ", " +
           percent(("extinct (L* < " + formatNumber("%g", v.extinctBelowL) + ")").c_str(), v.extinct) + ", " +
           percent(("saturated (C*ab > " + formatNumber("%g", v.saturatedAboveC) + ")").c_str(), v.saturated);
}

Image colourPicture(const ColourView& v, const std::string& title) {
    const int n = v.size, s = std::max(1, 480 / std::max(n, 1)), side = n * s;
    const int width = std::max(side + 20, 720);
    Image image(width, kTitleHeight + side + 12 + 4 * kLegendRow, {1, 1, 1});
    const int left = (width - side) / 2, top = kTitleHeight;
    const Vec3 background = v.white * kBackgroundY;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const size_t k = size_t(y) * size_t(n) + size_t(x);
            // Rays that missed the stone show the background, so the outline is anti-aliased.
            const double off = double(v.samples - v.stoneRays[k]) / double(v.samples);
            const Rgb c = display(v.xyz[k] + background * off);
            for (int dy = 0; dy < s; ++dy)
                for (int dx = 0; dx < s; ++dx) image.at(left + x * s + dx, top + y * s + dy) = c;
        }
    const std::string summary = colourSummary(v);
    const size_t cut = summary.find("; ");
    const std::string lines[3] = {title, summary.substr(0, cut), summary.substr(cut + 2)};
    for (int k = 0; k < 3; ++k) {
        const double scale =
            std::min(k == 0 ? 2.0 : 1.4, (width - 10) / std::max(1.0, textWidth(lines[k], 1)));
        drawText(image, width / 2.0, k == 0 ? 6 : 14 + 14.0 * k, lines[k], scale, kInk, Align::Center);
    }

    // A scale bar of a round length about a quarter of the view.
    const double span = 2 * v.halfWidthMm, pixelsPerMm = side / span;
    double bar = 0.1;
    for (double b : {0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0})
        if (b <= 0.3 * span) bar = b;
    const double y0 = top + side + 10;
    drawLine(image, {10, y0 + 8}, {10 + bar * pixelsPerMm, y0 + 8}, 3, kInk);
    drawLine(image, {10, y0 + 2}, {10, y0 + 14}, 1.5, kInk);
    drawLine(image, {10 + bar * pixelsPerMm, y0 + 2}, {10 + bar * pixelsPerMm, y0 + 14}, 1.5, kInk);
    drawText(image, 18 + bar * pixelsPerMm, y0 + 1,
             formatNumber("%g", bar) + " mm (stone " + formatNumber("%g", v.sizeMm) + " mm across)", 2, kInk);
    // The legend: the lighting, and the stone's mean colour as a swatch.
    const std::string light =
        "CIE illuminant " + std::string(kIlluminantNames.name(v.illuminant)) + " dome, head cone " +
        formatNumber("%g", v.headConeDeg) + " deg dark, ground reflectance " + formatNumber("%g", v.ground) +
        "; sRGB without white balance" + (v.absorbs ? "" : "; the material absorbs nothing");
    legendText(image, 10, y0 + kLegendRow + 3, light);
    const double y = y0 + 2 * kLegendRow;
    const Point2 box[4] = {Point2{10, y}, Point2{40, y}, Point2{40, y + 16}, Point2{10, y + 16}};
    fillPolygon(image, box, display(v.meanXyz));
    drawPolyline(image, box, true, 1, kInk);
    legendText(image, 48, y + 3,
               "mean colour of the face-up area: L* " + formatNumber("%.1f", v.meanLab.L) + ", a* " +
                   formatNumber("%.1f", v.meanLab.a) + ", b* " + formatNumber("%.1f", v.meanLab.b) + " (" +
                   std::to_string(v.pixels) + " pixels x " + std::to_string(v.samples) + " paths x " +
                   std::to_string(v.wavelengths) + " wavelengths)");
    return image;
}

}  // namespace facetlight
