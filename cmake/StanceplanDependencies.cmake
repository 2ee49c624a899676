# Every external package, found the way docs/DEPENDENCIES.md documents for Debian 12.
find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
pkg_check_modules(IPOPT REQUIRED IMPORTED_TARGET ipopt)
find_package(fcl 0.7 REQUIRED)        # the CMake config, not fcl.pc (which forces -std=c++11)
find_package(urdfdom REQUIRED)
find_package(assimp REQUIRED)
find_package(yaml-cpp REQUIRED)       # target `yaml-cpp` (0.7 has no namespaced target)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(Qhull REQUIRED)          # libqhull-dev: convex hulls of collision meshes
find_package(ompl 1.5 REQUIRED)       # libompl-dev: the computed guide path (planner/guide/); no imported target
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)  # also every gl* entry point: never link libGL
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)        # stb_truetype for captions (built into libstb)
find_package(PNG REQUIRED)            # libpng at compression level 1 (stb_image_write is 3x slower)
find_package(glfw3 3.3 REQUIRED)      # the panel's window (target `glfw`; it loads libGL itself with dlopen)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)    # Dear ImGui 1.86: static libimgui.a with the GLFW and OpenGL3 backends
# Optional: `render --video` (MP4) through FFmpeg's libraries, confined to render/image/video_file.cpp;
# without them the build works and --video says what to install.
pkg_check_modules(FFMPEG IMPORTED_TARGET libavcodec libavformat libswscale libavutil)
