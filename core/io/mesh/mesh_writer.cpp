#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include <memory>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/mesh/mesh_io.hpp"

namespace plumb {

void writeMesh(const std::filesystem::path& path, const BimModel& model) {
  std::string ext = path.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const char* format = ext == ".obj" ? "objnomtl" : ext == ".stl" ? "stlb" : nullptr;
  if (!format) throw FileError(path, "mesh export supports .obj, .stl and .ply (not '" + ext + "')");
  const TriangleMesh& mesh = model.mesh;
  if (mesh.triangles.empty()) throw InputError("the model has no triangles to write");

  // One assimp mesh (and node) per element, with its own compact vertex list.
  const bool tagged = model.triangle_element.size() == mesh.triangles.size() && !model.elements.empty();
  const std::size_t n_el = tagged ? model.elements.size() : 1;
  std::vector<std::vector<std::uint32_t>> tris_of(n_el);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) tris_of[tagged ? model.triangle_element[t] : 0].push_back(t);

  auto scene = std::make_unique<aiScene>();
  scene->mMaterials = new aiMaterial*[1]{new aiMaterial()};
  scene->mNumMaterials = 1;
  scene->mRootNode = new aiNode("root");
  std::vector<aiMesh*> meshes;
  std::vector<aiNode*> nodes;
  for (std::size_t e = 0; e < n_el; ++e) {
    if (tris_of[e].empty()) continue;
    auto* am = new aiMesh();
    am->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    am->mMaterialIndex = 0;
    std::vector<std::int64_t> local(mesh.vertices.size(), -1);
    std::vector<std::uint32_t> used;
    for (auto t : tris_of[e])
      for (auto v : mesh.triangles[t])
        if (local[v] < 0) {
          local[v] = static_cast<std::int64_t>(used.size());
          used.push_back(v);
        }
    am->mNumVertices = static_cast<unsigned>(used.size());
    am->mVertices = new aiVector3D[used.size()];
    for (std::size_t k = 0; k < used.size(); ++k) {
      const auto& p = mesh.vertices[used[k]];
      am->mVertices[k] = aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()), static_cast<ai_real>(p.z()));
    }
    am->mNumFaces = static_cast<unsigned>(tris_of[e].size());
    am->mFaces = new aiFace[am->mNumFaces];
    for (std::size_t f = 0; f < tris_of[e].size(); ++f) {
      const auto& tri = mesh.triangles[tris_of[e][f]];
      am->mFaces[f].mNumIndices = 3;
      am->mFaces[f].mIndices = new unsigned[3]{static_cast<unsigned>(local[tri[0]]), static_cast<unsigned>(local[tri[1]]),
                                                static_cast<unsigned>(local[tri[2]])};
    }
    std::string name = "mesh";
    if (tagged) {
      const auto& el = model.elements[e];
      name = el.type.empty() ? el.name : el.type + (el.name.empty() ? "" : "_" + el.name);
      if (name.empty()) name = "element_" + std::to_string(e);
    }
    for (auto& ch : name)
      if (ch == ' ' || ch == '\n' || ch == '\r') ch = '_';
    am->mName = aiString(name);
    auto* node = new aiNode(name);
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{static_cast<unsigned>(meshes.size())};
    node->mParent = scene->mRootNode;
    meshes.push_back(am);
    nodes.push_back(node);
  }
  scene->mNumMeshes = static_cast<unsigned>(meshes.size());
  scene->mMeshes = new aiMesh*[meshes.size()];
  std::copy(meshes.begin(), meshes.end(), scene->mMeshes);
  scene->mRootNode->mNumChildren = static_cast<unsigned>(nodes.size());
  scene->mRootNode->mChildren = new aiNode*[nodes.size()];
  std::copy(nodes.begin(), nodes.end(), scene->mRootNode->mChildren);

  Assimp::Exporter exporter;
  const aiExportDataBlob* blob = exporter.ExportToBlob(scene.get(), format);
  if (!blob) throw FileError(path, std::string("assimp could not export: ") + exporter.GetErrorString());
  AtomicFileWriter writer(path);
  writer.stream().write(static_cast<const char*>(blob->data), static_cast<std::streamsize>(blob->size));
  writer.commit();
}

}  // namespace plumb
