#include "colour_tables.h"

#include "colour/cie.h"
#include "colour/colour_space.h"

namespace facetlight::server {

nlohmann::json cieTablesJson() {
    using nlohmann::json;
    json wavelengths = json::array(), cmf = json::array(), powers = json::object(), whites = json::object();
    for (double nm = kCieFirstNm; nm <= kCieLastNm; nm += kCieStepNm) {
        wavelengths.push_back(nm);
        const Vec3 c = cieXyz(nm);
        cmf.push_back({c.x, c.y, c.z});
    }
    for (const auto& [illuminant, name] : kIlluminantNames.entries) {
        json rows = json::array();
        for (double nm = kCieFirstNm; nm <= kCieLastNm; nm += kCieStepNm)
            rows.push_back(illuminantPower(illuminant, nm));
        powers[std::string(name)] = std::move(rows);
        const Vec3 w = whitePoint(illuminant);
        whites[std::string(name)] = {w.x, w.y, w.z};
    }
    // The matrix's columns: the images of the unit vectors.
    const Vec3 cx = xyzToLinearSrgb({1, 0, 0}), cy = xyzToLinearSrgb({0, 1, 0}),
               cz = xyzToLinearSrgb({0, 0, 1});
    return {{"wavelength_nm", std::move(wavelengths)},
            {"xyz_bar", std::move(cmf)},
            {"illuminants", std::move(powers)},
            {"white_xyz", std::move(whites)},
            {"xyz_to_linear_srgb", {{cx.x, cy.x, cz.x}, {cx.y, cy.y, cz.y}, {cx.z, cy.z, cz.z}}}};
}

}  // namespace facetlight::server
