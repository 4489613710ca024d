# The browser build: the same sources, compiled by Debian's emscripten to WebAssembly, drawing with
# WebGL2 through emscripten's own GLFW. ./web.sh configures it (emcmake) with IMGUI_SOURCE_DIR set to
# Dear ImGui's Debian source package, unpacked under the build folder.
#
# Debian's header libraries are used as on the desktop, but never through -I/usr/include: that
# folder's C library would shadow emscripten's. Each one is linked into the build folder instead.
set(IMGUI_SOURCE_DIR "" CACHE PATH "Dear ImGui 1.86's source (apt-get source imgui; web.sh fetches it)")
set(LZ4_SOURCE_DIR "" CACHE PATH "LZ4's source, which FLANN calls (apt-get source lz4; web.sh fetches it)")
if(NOT EXISTS "${IMGUI_SOURCE_DIR}/imgui.cpp" OR NOT EXISTS "${LZ4_SOURCE_DIR}/lib/lz4hc.c")
  message(FATAL_ERROR "IMGUI_SOURCE_DIR='${IMGUI_SOURCE_DIR}' or LZ4_SOURCE_DIR='${LZ4_SOURCE_DIR}' is not a source "
          "folder: run ./web.sh, which fetches them")
endif()
set(WEB_INCLUDE ${CMAKE_BINARY_DIR}/include)
file(MAKE_DIRECTORY ${WEB_INCLUDE})
file(MAKE_DIRECTORY ${WEB_INCLUDE}/GL)
foreach(entry glm nlohmann eigen3 flann lz4.h lz4hc.h tiny_gltf.h tiny_obj_loader.h stb GL/glcorearb.h)
  if(NOT EXISTS /usr/include/${entry})
    message(FATAL_ERROR "/usr/include/${entry} is missing: tools/install_deps.sh web installs it")
  endif()
  file(CREATE_LINK /usr/include/${entry} ${WEB_INCLUDE}/${entry} SYMBOLIC)
endforeach()

# The GL loader, from the same header as the desktop's: the browser hands out WebGL2's functions by
# name, and those WebGL2 lacks stay null (gl::loadFunctions checks the ones we rely on).
set(GL_LOADER_DIR ${CMAKE_BINARY_DIR}/generated)
file(MAKE_DIRECTORY ${GL_LOADER_DIR})
add_custom_command(
  OUTPUT ${GL_LOADER_DIR}/gl_loader.h ${GL_LOADER_DIR}/gl_loader.cpp
  COMMAND python3 ${CMAKE_SOURCE_DIR}/tools/gen_gl_loader.py /usr/include/GL/glcorearb.h ${GL_LOADER_DIR}
  DEPENDS ${CMAKE_SOURCE_DIR}/tools/gen_gl_loader.py /usr/include/GL/glcorearb.h
  COMMENT "Generating the OpenGL core loader")

# Everything the desktop's core has, but for the desktop's own files (_desktop.cpp) and the grader's
# watchdog (a forked child per configuration: the page checks exercises in place).
file(GLOB WEB_SOURCES CONFIGURE_DEPENDS ${SHADELAB_CORE_GLOBS} app/ui/*.cpp app/web/*.cpp)
list(FILTER WEB_SOURCES EXCLUDE REGEX "(_desktop\\.cpp|app/grade/watchdog\\.cpp)$")
set(IMGUI_SOURCES ${IMGUI_SOURCE_DIR}/imgui.cpp ${IMGUI_SOURCE_DIR}/imgui_draw.cpp
  ${IMGUI_SOURCE_DIR}/imgui_tables.cpp ${IMGUI_SOURCE_DIR}/imgui_widgets.cpp
  ${IMGUI_SOURCE_DIR}/backends/imgui_impl_glfw.cpp ${IMGUI_SOURCE_DIR}/backends/imgui_impl_opengl3.cpp)

add_executable(shadelab ${WEB_SOURCES} app/cli/options.cpp app/cli/session.cpp app/context/gl_context.cpp
  ${IMGUI_SOURCES} ${LZ4_SOURCE_DIR}/lib/lz4.c ${LZ4_SOURCE_DIR}/lib/lz4hc.c
  ${GL_LOADER_DIR}/gl_loader.cpp)
set_target_properties(shadelab PROPERTIES OUTPUT_NAME shadelab SUFFIX ".js")
target_include_directories(shadelab PRIVATE ${CMAKE_SOURCE_DIR} ${GL_LOADER_DIR}
  ${IMGUI_SOURCE_DIR} ${IMGUI_SOURCE_DIR}/backends)
target_include_directories(shadelab SYSTEM PRIVATE ${WEB_INCLUDE} ${WEB_INCLUDE}/stb ${WEB_INCLUDE}/eigen3)
# In the page's file system the project's folders sit under /shadelab (the data file below).
target_compile_definitions(shadelab PRIVATE GLM_FORCE_SILENT_WARNINGS SHADELAB_SOURCE_DIR="/shadelab"
  GLFW_INCLUDE_NONE SHADELAB_HAS_WINDOW)
# ImGui's backend calls WebGL2 through emscripten's own GLES3 header, not through the loader.
set_source_files_properties(${IMGUI_SOURCE_DIR}/backends/imgui_impl_opengl3.cpp PROPERTIES
  COMPILE_DEFINITIONS IMGUI_IMPL_OPENGL_ES3)
# C++ exceptions as on the desktop (a throwing loader or job is caught and named, never an abort).
target_compile_options(shadelab PRIVATE -pthread -fexceptions -Wall -Wextra -Wno-unused-parameter)
# Threads for the jobs (smoothing, bakes, truths) off the page's main thread: the page is served with
# COOP/COEP (web.sh). A pool started with the page, so that no job waits for a worker to be made.
target_link_options(shadelab PRIVATE -pthread -fexceptions -sPTHREAD_POOL_SIZE=6 -sUSE_GLFW=3
  -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=268435456
  -sMAXIMUM_MEMORY=2147483648 -sENVIRONMENT=web,worker -sEXIT_RUNTIME=0 -sEXPORTED_RUNTIME_METHODS=[FS,addRunDependency,removeRunDependency,ccall]
  -lidbfs.js  # the student's folder, kept in the browser's storage (IndexedDB)
  --profiling-funcs  # function names in the .wasm: a stack trace in the console names them
  "SHELL:--preload-file ${CMAKE_SOURCE_DIR}/shaders@/shadelab/shaders"
  "SHELL:--preload-file ${CMAKE_SOURCE_DIR}/exercises@/shadelab/exercises")
# A course folder in the site beside the built-in exercises (./web.sh --exercises DIR), listed first.
set(SHADELAB_COURSE "" CACHE PATH "a course folder the page carries beside exercises/ (web.sh --exercises DIR)")
set(WEB_COURSE_FILES "")
if(SHADELAB_COURSE)
  target_link_options(shadelab PRIVATE "SHELL:--preload-file ${SHADELAB_COURSE}@/shadelab/course")
  file(GLOB_RECURSE WEB_COURSE_FILES CONFIGURE_DEPENDS ${SHADELAB_COURSE}/*)
endif()
# The preloaded folders go into shadelab.data when the program links: a changed shader or exercise
# file must link it again, or the page keeps the old one.
file(GLOB_RECURSE WEB_PRELOADED CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/shaders/* ${CMAKE_SOURCE_DIR}/exercises/*)
list(APPEND WEB_PRELOADED ${WEB_COURSE_FILES})
set_property(TARGET shadelab APPEND PROPERTY LINK_DEPENDS ${WEB_PRELOADED})
# The page around it: copied whenever it changes, whether or not the program was rebuilt.
set(WEB_PAGE index.html isolation.js course.js exercise.js)
list(TRANSFORM WEB_PAGE PREPEND ${CMAKE_SOURCE_DIR}/web/ OUTPUT_VARIABLE WEB_PAGE_SOURCES)
list(TRANSFORM WEB_PAGE PREPEND ${CMAKE_BINARY_DIR}/ OUTPUT_VARIABLE WEB_PAGE_COPIES)
add_custom_command(OUTPUT ${WEB_PAGE_COPIES}
  COMMAND ${CMAKE_COMMAND} -E copy ${WEB_PAGE_SOURCES} ${CMAKE_BINARY_DIR}
  DEPENDS ${WEB_PAGE_SOURCES})
add_custom_target(web_page ALL DEPENDS ${WEB_PAGE_COPIES})
