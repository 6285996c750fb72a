# Native build settings: warnings are errors, optional sanitizers, system header-only libraries.
set(NIWA_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Werror)
set(NIWA_THIRD_PARTY_INCLUDES "")  # glm, nlohmann, tinygltf, CLI11 live in /usr/include
if(NIWA_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()
# Link a binary that runs natively (no-op here; the WASM build sets node-runner flags).
function(niwa_node_program target)
endfunction()
