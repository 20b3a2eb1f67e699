#include "colour_tables.h"

#include "colour/cie.h"
#include "colour/colour_space.h"
#include "optics/absorption.h"
#include "util/error.h"

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

nlohmann::json absorptionByTransmission(const std::multimap<std::string, std::string>& query) {
    using nlohmann::json;
    json request = json::object();
    for (const auto& [key, value] : query) {
        if (request.contains(key)) throw Error(key, key + " is given twice");
        if (key != "path_mm" && key != "transmitted_colour" && key != "extraordinary_transmitted_colour")
            throw Error(key, key +
                                 " is not a parameter here: give transmitted_colour, and maybe "
                                 "extraordinary_transmitted_colour and path_mm");
        if (key == "path_mm") {
            size_t used = 0;
            double mm = 0;
            try {
                mm = std::stod(value, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != value.size() || value.empty()) throw Error(key, key + " must be a number (mm)");
            request[key] = mm;
        } else if (!value.empty() && value[0] != '#') {
            // "L*,a*,b*" as the job's [L*, a*, b*]; anything else the reader refuses by name.
            json lab = json::array();
            size_t start = 0;
            while (start <= value.size()) {
                const size_t comma = std::min(value.find(',', start), value.size());
                const std::string cell = value.substr(start, comma - start);
                size_t used = 0;
                try {
                    lab.push_back(std::stod(cell, &used));
                } catch (const std::exception&) {
                    used = 0;
                }
                if (used == 0 || used != cell.size())
                    throw Error(key, key + " must be \"#rrggbb\" or \"L*,a*,b*\"");
                start = comma + 1;
            }
            request[key] = std::move(lab);
        } else {
            request[key] = value;
        }
    }
    if (!request.contains("transmitted_colour"))
        throw Error("transmitted_colour", "transmitted_colour is missing (\"#rrggbb\" or \"L*,a*,b*\")");
    try {
        return toJson(readAbsorption(request, "absorption"));
    } catch (const Error& e) {
        // The query's own names, without the job's "absorption." in front.
        const std::string field = e.field().substr(e.field().find('.') + 1);
        std::string message = e.what();
        if (message.rfind("absorption.", 0) == 0) message = message.substr(11);
        if (const size_t at = message.find("'absorption."); at != std::string::npos)
            message.erase(at + 1, 11);
        throw Error(field, message);
    }
}

}  // namespace facetlight::server
