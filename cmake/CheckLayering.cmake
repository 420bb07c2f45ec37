# Script mode: cmake -DROOT=<tree> -P CheckLayering.cmake
cmake_minimum_required(VERSION 3.25)
# Fails when a file of engine/ or app/ includes a header of a layer above its own (or of a sibling), or
# a library its layer must not see (docs/architecture.md, "Layers"). Prints one line per violation.
if(NOT ROOT)
  message(FATAL_ERROR "CheckLayering: pass -DROOT=<source tree>")
endif()

# Layers, lowest first: "rank|name|folder". A file may include headers of its own layer and of layers
# of lower rank; layers of one rank are siblings and never include each other. The folder of the
# longest matching prefix decides a file's layer.
set(layers
    "1|geometry|engine/geometry"
    "1|spectrum|engine/spectrum"
    "2|tree|engine/tree"
    "3|optics|engine/optics"
    "4|scene|engine/scene"
    "5|transport|engine/transport"
    "5|wave|engine/wave"
    "6|tally|engine/tally"
    "7|run|engine/run"
    "8|edit|engine/edit"
    "9|results|app/results"
    "10|render|app/render"
    "11|snapshot|app/snapshot"
    "12|cli|app/cli"
    "12|gui|app/gui"
    "13|window|app/gui/window"
    "14|program|app"
    "13|python|python/module")
# Lower layers a layer must still not include: the window is the GUI's, not the command line's; the Python
# module is the command line's sibling, not the GUI's.
set(unrelated_window cli)
set(unrelated_python gui window)
# Include roots: a quoted include "X/..." is looked up under each of these, then beside the file.
set(include_roots engine app)
# Libraries a layer must not include (regular expressions on the <...> name), by layer name.
set(no_ui "^(GL|GLES[0-9]*|EGL|KHR|glad|epoxy|GLFW|glm|CLI|stb)/|^imgui")
set(forbidden_geometry "${no_ui}")
set(forbidden_spectrum "${no_ui}")
set(forbidden_tree "${no_ui}")
set(forbidden_optics "${no_ui}")
set(forbidden_scene "${no_ui}")
set(forbidden_transport "${no_ui}")
set(forbidden_wave "${no_ui}")
set(forbidden_tally "${no_ui}")
set(forbidden_run "${no_ui}")
set(forbidden_edit "${no_ui}")
# app/results writes every file format, PNG included (stb_image_write), and nothing else of the UI.
set(forbidden_results "^(GL|GLES[0-9]*|EGL|KHR|glad|epoxy|GLFW|glm|CLI)/|^imgui|^stb/stb_image\\.h")
set(forbidden_render "^(GLFW|CLI)/|^imgui|^GL/osmesa")
set(forbidden_program "^(GLFW|CLI)/|^imgui")
set(forbidden_snapshot "^(GLFW|CLI)/|^imgui")
set(forbidden_cli "^GLFW/|^imgui")
set(forbidden_gui "^(GLFW|CLI)/")
set(forbidden_window "^CLI/")
set(forbidden_python "^(GL|GLES[0-9]*|EGL|KHR|glad|epoxy|GLFW|glm|CLI|stb)/|^imgui")

# Sets <out_rank> and <out_name> to the layer of `path` (relative to ROOT), or empty.
function(layer_of path out_rank out_name)
  set(best_length 0)
  set(rank "")
  set(name "")
  foreach(entry ${layers})
    string(REPLACE "|" ";" fields "${entry}")
    list(GET fields 0 entry_rank)
    list(GET fields 1 entry_name)
    list(GET fields 2 folder)
    string(LENGTH "${folder}/" length)
    string(SUBSTRING "${path}" 0 ${length} head)
    if(head STREQUAL "${folder}/" AND length GREATER best_length)
      set(best_length ${length})
      set(rank ${entry_rank})
      set(name ${entry_name})
    endif()
  endforeach()
  set(${out_rank} "${rank}" PARENT_SCOPE)
  set(${out_name} "${name}" PARENT_SCOPE)
endfunction()

set(patterns "")
foreach(folder engine app python)
  foreach(extension cpp hpp h cc hh inl ipp)
    list(APPEND patterns "${ROOT}/${folder}/*.${extension}")
  endforeach()
endforeach()
file(GLOB_RECURSE files RELATIVE "${ROOT}" ${patterns})
set(violations 0)
foreach(file ${files})
  layer_of("${file}" own_rank own_name)
  if(own_rank STREQUAL "")
    continue()
  endif()
  get_filename_component(own_dir "${file}" DIRECTORY)
  file(STRINGS "${ROOT}/${file}" includes ENCODING UTF-8 REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
  foreach(line ${includes})
    set(target "")
    if(line MATCHES "include[ \t]*<([^>]+)>")
      set(header "${CMAKE_MATCH_1}")
      if(DEFINED forbidden_${own_name} AND header MATCHES "${forbidden_${own_name}}")
        message("${file}: includes <${header}>, which layer ${own_name} must not use")
        math(EXPR violations "${violations} + 1")
        continue()
      endif()
      set(quoted "<${header}>")
    elseif(line MATCHES "include[ \t]*\"([^\"]+)\"")
      set(header "${CMAKE_MATCH_1}")
      set(quoted "\"${header}\"")
      # Beside the file first (normalised, so "../cli/Cli.hpp" is app/cli's), as the compiler looks.
      set(beside "${own_dir}/${header}")
      cmake_path(NORMAL_PATH beside)
      if(EXISTS "${ROOT}/${beside}" AND NOT beside MATCHES "^\\.\\./")
        set(target "${beside}")
      endif()
    else()
      continue()
    endif()
    # Our own headers through the include roots, in quotes or angle brackets (both compile with -I).
    if(target STREQUAL "")
      foreach(root ${include_roots})
        if(EXISTS "${ROOT}/${root}/${header}")
          set(target "${root}/${header}")
          break()
        endif()
      endforeach()
    endif()
    if(target STREQUAL "")
      continue()  # generated or third-party
    endif()
    layer_of("${target}" their_rank their_name)
    if(their_name STREQUAL own_name OR their_rank STREQUAL "")
      continue()
    endif()
    if(DEFINED unrelated_${own_name} AND their_name IN_LIST unrelated_${own_name})
      message("${file}: includes ${quoted} of layer ${their_name}, which layer ${own_name} must not use")
      math(EXPR violations "${violations} + 1")
    elseif(their_rank GREATER_EQUAL own_rank)
      if(their_rank EQUAL own_rank)
        set(why "a sibling")
      else()
        set(why "above it")
      endif()
      message("${file}: includes ${quoted} of layer ${their_name}, ${why} (layer ${own_name})")
      math(EXPR violations "${violations} + 1")
    endif()
  endforeach()
endforeach()

list(LENGTH files checked)
if(violations GREATER 0)
  message(FATAL_ERROR "layering: ${violations} include(s) break the layers of docs/architecture.md")
endif()
message("layering: ${checked} files, every include within its layer or below")
