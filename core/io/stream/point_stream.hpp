#pragma once
// Streaming reads of point files (docs/IO.md): streamDataset hands a file to a
// ChunkSink (chunk_sink.hpp) scan by scan, in chunks, so the memory a consumer needs is
// bounded by the chunk size, not the file:
// - E57: one compressed-vector packet, one decoded block (<= 4 MiB) and one chunk at a time.
// - LAS: one block of records and one chunk at a time.
// - PLY (ASCII and binary): one chunk of vertices, one 1 MiB read window per thread, one line.
// - Text (.xyz .txt .csv .pts .asc): one 4 MiB block cut at a line end and one chunk.
// - PCD (ASCII, binary, binary_compressed): read whole (PCL, in the import helper), then
//   handed over in chunks (its memory is that of readDataset; see the doc).
// Chunks hold the values readDataset gives (same offsets, same columns, same numbers), so a
// consumer's result does not depend on the route.
#include <filesystem>

#include "common/progress.hpp"
#include "io/io.hpp"
#include "io/stream/chunk_sink.hpp"

namespace plumb {

/// True when `path` is streamed without reading it whole: E57, LAS, text, and PLY without faces
/// (a PLY whose header cannot be read: false, the whole reader reports it).
bool streamsInChunks(const std::filesystem::path& path);

/// Streams a point file to `sink`; format and errors as readDataset (FileError naming the
/// file, the problem and where; model files are refused). Throws what the sink throws.
void streamDataset(const std::filesystem::path& path, const StreamOptions& options, ChunkSink& sink,
                   Progress* progress = nullptr);

/// The outline of a file that streamsInChunks (its header: format, scans with names, poses,
/// fields and record counts) without reading a point. The metadata is the header's (the parts
/// known only after the points are missing). Errors as streamDataset.
StreamOutline readStreamOutline(const std::filesystem::path& path);

/// Hands a dataset already in memory to `sink` in chunks (the route for formats read whole;
/// also lets a consumer take a Dataset and a file alike).
void streamInMemory(Dataset data, const StreamOptions& options, ChunkSink& sink);

}  // namespace plumb
