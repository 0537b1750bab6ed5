#pragma once
// The stream plumb-import --pcd writes on its output and readPcd decodes: the cloud PCL read
// (layout + raw point records) or the error the read ended with.
//
// Layout (io/isolation/helper_stream.hpp): "PLUMBPCD", u32 version 1, u8 kind.
// kind 1, cloud: u32 width, height, point_step; u32 n + n x (string name, u32 offset,
// u8 datatype, u32 count) fields; 7 x double viewpoint; u64 n + n point bytes.
// kind 2, error: the failure record of helper_stream.hpp.
// Both end with "END!". The decoder checks every count against the bytes left and the layout
// against the point bytes and point_step (layoutProblem), so a damaged stream is an error.
#include <cstdint>
#include <span>
#include <string_view>
#include <variant>

#include "io/isolation/helper_stream.hpp"
#include "io/pcd/pcd_layout.hpp"

namespace plumb::pcd_stream {

/// A decoded cloud; `points` points into the decoded bytes (no copy).
struct Cloud {
  PcdLayout layout;
  std::span<const std::uint8_t> points;
};

/// Writes to a file descriptor (the points straight from `points`); false if it refused them.
bool writeCloud(int fd, const PcdLayout& layout, std::span<const std::uint8_t> points);
bool writeFailure(int fd, const helper_stream::Failure& failure);

/// Decodes a whole stream. Throws std::runtime_error saying what is wrong with it.
std::variant<Cloud, helper_stream::Failure> decode(std::string_view bytes);

}  // namespace plumb::pcd_stream
