# Included by tests/fuzz/standalone/CMakeLists.txt for fuzz_model. There is no core/io/model:
# the parsers Plumb runs in its own process on a model's bytes are spread over core/io/mesh
# (the IFC pre-pass, the model stream, the crash report's entity scan, node names) and
# core/io/isolation (the stream reader and the wording of a helper run). mesh_reader.cpp
# (which starts the helper) and mesh_writer.cpp (assimp's exporter) are left out.
set(_fuzz_model_mesh ifc_georef ifc_map_conversion ifc_node_name import_failure model_stream step_entities)
list(TRANSFORM _fuzz_model_mesh PREPEND ${S}/core/io/mesh/)
list(TRANSFORM _fuzz_model_mesh APPEND .cpp)
file(GLOB _fuzz_model_isolation ${S}/core/io/isolation/*.cpp)
target_sources(fuzz_model PRIVATE ${_fuzz_model_mesh} ${_fuzz_model_isolation})
target_include_directories(fuzz_model PRIVATE ${S}/tests)  # support/ifc_prepass_checks.hpp
