#include "io/lod/lod_node_output.hpp"

#include "common/error.hpp"
#include "io/lod/lod_format.hpp"

namespace plumb {

LodNodeOutput::LodNodeOutput(const std::filesystem::path& points_file, bool has_intensity, bool has_rgb)
    : file_(points_file), has_intensity_(has_intensity), has_rgb_(has_rgb) {
  const std::string header = lodPointsHeader();
  file_.stream().write(header.data(), static_cast<std::streamsize>(header.size()));
  bytes_ = header.size();
}

void LodNodeOutput::write(const LodKey& key, const std::vector<LodPoint>& points) {
  const auto [it, fresh] = entries_.try_emplace(mapKey(key), Entry{bytes_, points.size()});
  if (!fresh) throw std::logic_error("level-of-detail node written twice");
  const std::string data = encodeLodPoints(points, has_intensity_, has_rgb_);
  file_.stream().write(data.data(), static_cast<std::streamsize>(data.size()));
  if (!file_.stream()) throw FileError(file_.target(), "cannot write the level-of-detail points", atByte(bytes_));
  bytes_ += data.size();
  points_ += points.size();
}

void LodNodeOutput::visit(const LodGrid& grid, const LodKey& key, std::uint32_t parent,
                          std::vector<LodNode>& out) const {
  const auto it = entries_.find(mapKey(key));
  if (it == entries_.end()) return;
  LodNode n;
  n.id = static_cast<std::uint32_t>(out.size());
  n.parent = parent;
  n.key = key;
  n.bounds = grid.bounds(key);
  n.spacing = grid.spacing(key.depth);
  n.point_count = it->second.count;
  n.data_offset = it->second.offset;
  out.push_back(n);
  for (int o = 0; o < 8; ++o) {
    const std::size_t before = out.size();
    visit(grid, key.child(o), n.id, out);
    if (out.size() > before) out[n.id].children[o] = static_cast<std::uint32_t>(before);
  }
}

std::vector<LodNode> LodNodeOutput::nodes(const LodGrid& grid) const {
  std::vector<LodNode> out;
  out.reserve(entries_.size());
  visit(grid, LodKey{}, kNoLodNode, out);
  if (out.size() != entries_.size()) throw std::logic_error("level-of-detail node without its parent");
  return out;
}

}  // namespace plumb
