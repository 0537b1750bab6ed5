#pragma once
// Models that break assimp, written by the tests that check Plumb survives them: duplex.ifc
// with one entity line deleted, glTF/COLLADA node chains deeper than assimp's recursion can go,
// an OBJ with one huge polygon.
#include <filesystem>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "support/test_support.hpp"

namespace plumb::test {

/// duplex.ifc without the line starting with `prefix` (e.g. "#8961=" -> assimp SIGSEGV).
inline std::filesystem::path duplexWithout(const std::filesystem::path& dir, const std::string& prefix,
                                           const std::string& name) {
  std::ifstream in(sharedData("ifc/duplex.ifc"));
  std::ostringstream out;
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(prefix, 0) != 0) out << line << '\n';
  writeAll(dir / name, out.str());
  return dir / name;
}

/// A glTF whose `depth` nodes each hold the next; the last has a one-triangle mesh.
inline std::filesystem::path deepGltf(const std::filesystem::path& dir, int depth) {
  std::string nodes;
  for (int i = 0; i + 1 < depth; ++i) nodes += "{\"children\":[" + std::to_string(i + 1) + "]},";
  nodes += "{\"mesh\":0}";
  writeAll(dir / "deep.gltf",
           R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[)" + nodes +
               R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,2,0]}],
"bufferViews":[{"buffer":0,"byteLength":36}],
"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAAEAAAAAA"}]})");
  return dir / "deep.gltf";
}

/// A COLLADA file whose visual scene nests `depth` nodes; the innermost instances a triangle.
inline std::filesystem::path deepDae(const std::filesystem::path& dir, int depth) {
  std::string open, close;
  for (int i = 0; i < depth; ++i) {
    open += "<node id=\"n" + std::to_string(i) + "\">";
    close += "</node>";
  }
  writeAll(dir / "deep.dae",
           R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<asset><up_axis>Z_UP</up_axis></asset>
<library_geometries><geometry id="g"><mesh>
<source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>
<technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/>
<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles>
</mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s">)" +
               open + "<instance_geometry url=\"#g\"/>" + close +
               R"(</visual_scene></library_visual_scenes>
<scene><instance_visual_scene url="#s"/></scene></COLLADA>
)");
  return dir / "deep.dae";
}

/// An OBJ with one polygon of `n` vertices on a circle (assimp triangulates it in O(n^2)+).
inline std::filesystem::path hugePolygonObj(const std::filesystem::path& dir, int n) {
  std::ostringstream s;
  for (int i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * i / n;
    s << "v " << 10 * std::cos(a) << ' ' << 10 * std::sin(a) << " 0\n";
  }
  s << "f";
  for (int i = 1; i <= n; ++i) s << ' ' << i;
  s << '\n';
  writeAll(dir / "huge_polygon.obj", s.str());
  return dir / "huge_polygon.obj";
}

}  // namespace plumb::test
