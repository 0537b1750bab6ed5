#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "common/error.hpp"
#include "io/mesh/mesh_io.hpp"

namespace plumb {
namespace {

std::string lowerExtension(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool isHelperNode(const std::string& name) {
  return name.empty() || name[0] == '$' || name.rfind("IfcMappedItem", 0) == 0;
}

/// FILE_SCHEMA(('IFC4')) of an IFC file's header, or "".
std::string ifcSchema(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  for (int i = 0; i < 200 && std::getline(in, line); ++i) {
    const auto k = line.find("FILE_SCHEMA");
    if (k == std::string::npos) continue;
    const auto a = line.find('\'', k);
    const auto b = a == std::string::npos ? a : line.find('\'', a + 1);
    if (b != std::string::npos) return line.substr(a + 1, b - a - 1);
  }
  return "";
}

/// 1-based line where "#id=" starts an entity in an IFC file (0 if not found).
std::uint64_t ifcEntityLine(const std::filesystem::path& path, const std::string& id) {
  std::ifstream in(path);
  std::string line;
  const std::string key = "#" + id;
  for (std::uint64_t n = 1; std::getline(in, line); ++n)
    if (line.rfind(key, 0) == 0 && line.size() > key.size() &&
        (line[key.size()] == '=' || line[key.size()] == ' '))
      return n;
  return 0;
}

[[noreturn]] void throwImportError(const std::filesystem::path& path, const std::string& err) {
  if (lowerExtension(path) != ".ifc") throw FileError(path, "assimp cannot read this file: " + err);
  // e.g. "(entity #20909) type error reading literal field - expected argument 9 to IfcSpace to be a `IfcInternalOrExternalEnum`"
  std::smatch m;
  std::string entity_id, entity_type;
  if (std::regex_search(err, m, std::regex(R"(entity #(\d+))"))) entity_id = m[1];
  if (std::regex_search(err, m, std::regex(R"(to (Ifc[A-Za-z0-9]+))"))) entity_type = m[1];
  const std::string schema = ifcSchema(path);
  std::string msg = "assimp cannot read this IFC";
  if (!schema.empty()) msg += " (schema " + schema + ")";
  if (!entity_id.empty()) msg += ": it fails on entity #" + entity_id + (entity_type.empty() ? "" : " (" + entity_type + ")");
  msg += ": " + err +
         ". assimp 5.2 reads IFC2X3 and only part of IFC4: export the model from the authoring tool as "
         "IFC2X3, or as glTF/OBJ, and import that file";
  FileLocation loc;
  if (!entity_id.empty()) {
    loc.element = "entity #" + entity_id + (entity_type.empty() ? "" : " " + entity_type);
    if (auto line = ifcEntityLine(path, entity_id)) loc.line = line;
  }
  throw FileError(path, msg, loc);
}

struct Walker {
  const aiScene* scene;
  bool ifc;
  Eigen::Matrix4d axes;  ///< applied after the node transforms (Y-up -> Z-up, units)
  BimModel* model;
  std::map<const aiNode*, std::uint32_t> element_of_node;

  std::uint32_t elementFor(const aiNode* node, const aiMesh* mesh) {
    const aiNode* owner = node;
    if (ifc)
      while (owner->mParent && isHelperNode(owner->mName.C_Str())) owner = owner->mParent;
    auto it = element_of_node.find(owner);
    if (it != element_of_node.end()) return it->second;
    BimElement e;
    if (ifc) {
      e = elementFromIfcNodeName(owner->mName.C_Str());
    } else {
      e.name = owner->mName.length ? owner->mName.C_Str() : mesh->mName.C_Str();
    }
    model->elements.push_back(e);
    const auto idx = static_cast<std::uint32_t>(model->elements.size() - 1);
    element_of_node.emplace(owner, idx);
    return idx;
  }

  void walk(const aiNode* node, const aiMatrix4x4& parent) {
    const aiMatrix4x4 m = parent * node->mTransformation;
    Eigen::Matrix4d t;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) t(r, c) = m[r][c];
    t = axes * t;
    const Eigen::Matrix3d normal_m = t.topLeftCorner<3, 3>().inverse().transpose();
    auto& mesh = model->mesh;
    for (unsigned k = 0; k < node->mNumMeshes; ++k) {
      const aiMesh* am = scene->mMeshes[node->mMeshes[k]];
      if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
      const std::uint32_t el = elementFor(node, am);
      const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
      for (unsigned v = 0; v < am->mNumVertices; ++v) {
        const aiVector3D& p = am->mVertices[v];
        mesh.vertices.push_back((t * Eigen::Vector4d(p.x, p.y, p.z, 1.0)).head<3>());
      }
      if (am->mNormals && with_normals) {
        for (unsigned v = 0; v < am->mNumVertices; ++v) {
          const aiVector3D& nn = am->mNormals[v];
          mesh.vertex_normals.push_back((normal_m * Eigen::Vector3d(nn.x, nn.y, nn.z)).normalized().cast<float>());
        }
      } else if (with_normals) {
        with_normals = false;  // some mesh lacks normals: drop them all
        mesh.vertex_normals.clear();
      }
      for (unsigned f = 0; f < am->mNumFaces; ++f) {
        const aiFace& face = am->mFaces[f];
        if (face.mNumIndices != 3) continue;
        mesh.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
        model->triangle_element.push_back(el);
      }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c) walk(node->mChildren[c], m);
  }
  bool with_normals = true;
};

}  // namespace

BimElement elementFromIfcNodeName(const std::string& node_name) {
  BimElement e;
  if (node_name.rfind("Ifc", 0) != 0) {
    e.name = node_name;
    return e;
  }
  const auto first = node_name.find('_');
  e.type = node_name.substr(0, first);
  std::string rest = first == std::string::npos ? "" : node_name.substr(first + 1);
  // GlobalId: 22 characters of IFC's base-64 alphabet at the end, after an underscore.
  if (rest.size() >= 23 && rest[rest.size() - 23] == '_') {
    e.guid = rest.substr(rest.size() - 22);
    rest = rest.substr(0, rest.size() - 23);
  } else if (rest.size() == 22) {
    e.guid = rest;
    rest.clear();
  }
  e.name = rest;
  for (const char* suffix : {"StandardCase", "ElementedCase"}) {
    const std::string s(suffix);
    if (e.type.size() > s.size() && e.type.compare(e.type.size() - s.size(), s.size(), s) == 0)
      e.type.erase(e.type.size() - s.size());
  }
  return e;
}

BimModel readMesh(const std::filesystem::path& path, Progress* progress) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw FileError(path, "no such file");
  if (std::filesystem::file_size(path, ec) == 0) throw FileError(path, "file is empty (0 bytes)");
  reportProgress(progress, 0.0, "importing model");
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (!scene) throwImportError(path, importer.GetErrorString());
  if (!scene->mRootNode) throw FileError(path, "assimp returned a scene without nodes");
  checkCanceled(progress);
  reportProgress(progress, 0.7, "converting model");

  const std::string ext = lowerExtension(path);
  BimModel model;
  model.source = path;
  model.format = ext.size() > 1 ? ext.substr(1) : "";
  if (model.format == "glb") model.format = "gltf";
  Walker w{scene, ext == ".ifc", Eigen::Matrix4d::Identity(), &model, {}};
  double scale = 1.0;
  if (ext == ".fbx" && scene->mMetaData) {
    double unit = 0;
    float unitf = 0;
    if (scene->mMetaData->Get("UnitScaleFactor", unit) && unit > 0) scale = unit / 100.0;
    else if (scene->mMetaData->Get("UnitScaleFactor", unitf) && unitf > 0) scale = unitf / 100.0;
  }
  const bool y_up = ext == ".ifc" || ext == ".gltf" || ext == ".glb" || ext == ".dae" || ext == ".fbx";
  if (y_up) {
    w.axes.topLeftCorner<3, 3>() << 1, 0, 0,  //
        0, 0, -1,                              //
        0, 1, 0;                               // (x, y, z) -> (x, -z, y)
  }
  w.axes.topLeftCorner<3, 3>() *= scale;
  w.walk(scene->mRootNode, aiMatrix4x4());
  if (model.mesh.triangles.empty()) throw FileError(path, "the file holds no triangles (no surface geometry)");
  if (!w.with_normals) model.mesh.vertex_normals.clear();
  reportProgress(progress, 1.0, "importing model");
  return model;
}

}  // namespace plumb
