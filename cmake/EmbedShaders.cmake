# Script mode: cmake -DOUTPUT=file.cpp -DINPUTS="a.vert|b.frag" -P EmbedShaders.cmake
# Writes a C++ source with every shader's text, so the binary needs no shaders/ folder at run time.
string(REPLACE "|" ";" inputs "${INPUTS}")
set(entries "")
foreach(input ${inputs})
  file(READ ${input} text)
  get_filename_component(name ${input} NAME)
  string(FIND "${text}" ")glsl\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${input} contains the raw-string delimiter )glsl\"")
  endif()
  string(APPEND entries "    {\"${name}\", R\"glsl(${text})glsl\"},\n")
endforeach()
file(WRITE ${OUTPUT}.new "// Generated from shaders/*.glsl by cmake/EmbedShaders.cmake; do not edit.\n"
     "#include \"render/ShaderSources.hpp\"\n\n"
     "namespace dropscope::render {\n\n"
     "const std::vector<EmbeddedShader>& embeddedShaders() {\n"
     "    static const std::vector<EmbeddedShader> shaders{\n${entries}    };\n"
     "    return shaders;\n}\n\n}  // namespace dropscope::render\n")
file(COPY_FILE ${OUTPUT}.new ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.new)
