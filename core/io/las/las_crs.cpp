#include "io/las/las_crs.hpp"

#include "common/proj_context.hpp"

#include <cctype>
#include <cstring>
#include <memory>

namespace plumb::las {
namespace {

/// The code of a plain "EPSG:<digits>" text, else 0.
int epsgCode(const std::string& crs) {
  if (crs.rfind("EPSG:", 0) != 0 || crs.size() == 5 || crs.size() > 14) return 0;
  for (std::size_t i = 5; i < crs.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(crs[i]))) return 0;
  const long code = std::stol(crs.substr(5));
  return code > 0 && code < 65535 ? static_cast<int>(code) : 0;
}

/// GeoKeyDirectory with one key: ProjectedCSTypeGeoKey (3072) or GeographicTypeGeoKey (2048).
std::vector<std::uint8_t> geoKeys(int code, bool geographic) {
  const std::uint16_t words[] = {1, 1, 0, 1, static_cast<std::uint16_t>(geographic ? 2048 : 3072),
                                 0, 1, static_cast<std::uint16_t>(code)};
  std::vector<std::uint8_t> out(sizeof words);
  std::memcpy(out.data(), words, sizeof words);
  return out;
}

CrsRecord wktRecord(const char* wkt) {
  CrsRecord r{2112, "OGC coordinate system WKT", {}};
  r.payload.assign(wkt, wkt + std::strlen(wkt));
  r.payload.push_back(0);
  return r;
}

bool isGeographic(const PJ* crs) {
  const PJ_TYPE t = proj_get_type(crs);
  return t == PJ_TYPE_GEOGRAPHIC_2D_CRS || t == PJ_TYPE_GEOGRAPHIC_3D_CRS;
}

}  // namespace

std::optional<CrsRecord> crsRecord(const std::string& crs, bool las14,
                                   std::vector<std::string>& notes) {
  if (crs.empty()) return std::nullopt;
  ProjContext proj;
  ProjObject obj(proj_create(proj.ctx, crs.c_str()), &proj_destroy);
  if (!obj || !proj_is_crs(obj.get())) {
    notes.push_back("coordinate system '" + crs.substr(0, 80) +
                    "' was not written: it is not an EPSG code or WKT that PROJ knows");
    return std::nullopt;
  }
  const int code = epsgCode(crs);
  if (code && !las14 && code < 32767) return CrsRecord{34735, "GeoTIFF GeoKeyDirectoryTag",
                                                       geoKeys(code, isGeographic(obj.get()))};
  if (!code) return wktRecord(crs.c_str());  // WKT text as the user's file had it
  const char* wkt = proj_as_wkt(proj.ctx, obj.get(), PJ_WKT1_GDAL, nullptr);
  if (!wkt) wkt = proj_as_wkt(proj.ctx, obj.get(), PJ_WKT2_2019, nullptr);
  if (!wkt) {
    notes.push_back("coordinate system " + crs + " was not written: PROJ has no WKT for it");
    return std::nullopt;
  }
  return wktRecord(wkt);
}

}  // namespace plumb::las
