// assimp scene -> BimModel, inside the plumb-import helper. The node tree is walked with an
// explicit stack: deeply nested files must not overflow ours once assimp has read them.
#include "io/mesh/helper/assimp_reader.hpp"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <map>
#include <vector>

#include "common/error.hpp"
#include "io/mesh/file_extension.hpp"
#include "io/mesh/mesh_io.hpp"

namespace plumb::import_helper {
namespace {

bool isHelperNode(const std::string& name) {
  return name.empty() || name[0] == '$' || name.rfind("IfcMappedItem", 0) == 0;
}

/// The storey of an IFC node: assimp nests each element under the spatial structure that
/// contains it (site, building, storey, space), so the nearest ancestor named
/// "IfcBuildingStorey_..." is its storey: the node's name part (assimp drops its spaces; the
/// reader names it again from the file, io/mesh/ifc_storeys.hpp) and its GlobalId.
void setStoreyOf(const aiNode* node, BimElement& e) {
  for (const aiNode* n = node ? node->mParent : nullptr; n; n = n->mParent) {
    const std::string name = n->mName.C_Str();
    if (name.rfind("IfcBuildingStorey", 0) != 0) continue;
    const BimElement storey = elementFromIfcNodeName(name);
    e.storey = storey.name.empty() ? storey.guid : storey.name;
    e.storey_guid = storey.guid;
    return;
  }
}

struct Walker {
  const aiScene* scene;
  bool ifc;
  Eigen::Matrix4d axes;  ///< applied after the node transforms (Y-up -> Z-up, units)
  BimModel* model;
  std::map<const aiNode*, std::uint32_t> element_of_node;
  bool with_normals = true;

  std::uint32_t elementFor(const aiNode* node, const aiMesh* mesh) {
    const aiNode* owner = node;
    if (ifc)
      while (owner->mParent && isHelperNode(owner->mName.C_Str())) owner = owner->mParent;
    auto it = element_of_node.find(owner);
    if (it != element_of_node.end()) return it->second;
    BimElement e;
    const std::string label = owner->mName.length ? owner->mName.C_Str() : mesh->mName.C_Str();
    // Plumb's own OBJ/glTF export names each element's group "<IfcType>_<name>": read it back.
    if (ifc || looksLikeIfcNodeName(label)) e = elementFromIfcNodeName(ifc ? owner->mName.C_Str() : label);
    else e.name = label;
    if (ifc) setStoreyOf(owner, e);
    model->elements.push_back(e);
    const auto idx = static_cast<std::uint32_t>(model->elements.size() - 1);
    element_of_node.emplace(owner, idx);
    return idx;
  }

  void addNormals(const aiMesh* am, const Eigen::Matrix3d& normal_m) {
    if (!with_normals) return;
    if (!am->mNormals) {
      with_normals = false;  // some mesh lacks normals: drop them all
      model->mesh.vertex_normals.clear();
      return;
    }
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      const aiVector3D& nn = am->mNormals[v];
      model->mesh.vertex_normals.push_back((normal_m * Eigen::Vector3d(nn.x, nn.y, nn.z)).normalized().cast<float>());
    }
  }

  void addMesh(const aiNode* node, const aiMesh* am, const Eigen::Matrix4d& t) {
    auto& mesh = model->mesh;
    const std::uint32_t el = elementFor(node, am);
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      const aiVector3D& p = am->mVertices[v];
      mesh.vertices.push_back((t * Eigen::Vector4d(p.x, p.y, p.z, 1.0)).head<3>());
    }
    addNormals(am, t.topLeftCorner<3, 3>().inverse().transpose());
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
      model->triangle_element.push_back(el);
    }
  }

  void visit(const aiNode* node, const aiMatrix4x4& m) {
    Eigen::Matrix4d t;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) t(r, c) = m[r][c];
    t = axes * t;
    for (unsigned k = 0; k < node->mNumMeshes; ++k) {
      const aiMesh* am = scene->mMeshes[node->mMeshes[k]];
      if (am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) addMesh(node, am, t);
    }
  }

  /// Depth first, children in order (as the recursive walk did).
  void walk(const aiNode* root) {
    std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack{{root, root->mTransformation}};
    while (!stack.empty()) {
      const auto [node, m] = stack.back();
      stack.pop_back();
      visit(node, m);
      for (unsigned c = node->mNumChildren; c-- > 0;)
        stack.emplace_back(node->mChildren[c], m * node->mChildren[c]->mTransformation);
    }
  }
};

/// IFC, glTF, COLLADA and FBX come from assimp Y-up: (x, y, z) -> (x, -z, y); FBX units too.
Eigen::Matrix4d axesFor(const std::string& ext, const aiScene* scene) {
  Eigen::Matrix4d axes = Eigen::Matrix4d::Identity();
  double scale = 1.0;
  if (ext == ".fbx" && scene->mMetaData) {
    double unit = 0;
    float unitf = 0;
    if (scene->mMetaData->Get("UnitScaleFactor", unit) && unit > 0) scale = unit / 100.0;
    else if (scene->mMetaData->Get("UnitScaleFactor", unitf) && unitf > 0) scale = unitf / 100.0;
  }
  const bool y_up = ext == ".ifc" || ext == ".gltf" || ext == ".glb" || ext == ".dae" || ext == ".fbx";
  if (y_up) {
    axes.topLeftCorner<3, 3>() << 1, 0, 0,  //
        0, 0, -1,                           //
        0, 1, 0;
  }
  axes.topLeftCorner<3, 3>() *= scale;
  return axes;
}

}  // namespace

BimModel importWithAssimp(const std::filesystem::path& path) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (!scene) throwImportError(path, importer.GetErrorString());
  if (!scene->mRootNode) throw FileError(path, "assimp returned a scene without nodes");

  const std::string ext = lowerExtension(path);
  BimModel model;
  model.format = ext.size() > 1 ? ext.substr(1) : "";
  if (model.format == "glb") model.format = "gltf";
  Walker w{scene, ext == ".ifc", axesFor(ext, scene), &model, {}};
  w.walk(scene->mRootNode);
  if (model.mesh.triangles.empty()) throw FileError(path, "the file holds no triangles (no surface geometry)");
  if (!w.with_normals) model.mesh.vertex_normals.clear();
  return model;
}

}  // namespace plumb::import_helper
