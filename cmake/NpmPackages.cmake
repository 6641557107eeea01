# npm packages the build needs (uPlot, embedded into kontaktd; playwright-core, for the
# browser tests), pinned by a committed package-lock.json and installed by `npm ci` into the
# build tree at build time: nothing is downloaded at run time, nothing lands in the sources.
find_program(KONTAKT_NPM npm)
if(NOT KONTAKT_NPM)
  message(FATAL_ERROR "npm not found: run deploy/install-deps.sh (the dashboard embeds uPlot from npm)")
endif()

# kontakt_npm_ci(TARGET <name> PACKAGE_DIR <dir with package.json + package-lock.json>
#                FILES <paths under node_modules/ the build uses> OUT_DIR <var>)
# Adds target <name> (part of ALL) and sets <var> to the folder holding node_modules/.
function(kontakt_npm_ci)
  cmake_parse_arguments(A "" "TARGET;PACKAGE_DIR;OUT_DIR" "FILES" ${ARGN})
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/npm-${A_TARGET})
  file(MAKE_DIRECTORY ${dir})
  list(TRANSFORM A_FILES PREPEND ${dir}/node_modules/ OUTPUT_VARIABLE outputs)
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ${CMAKE_COMMAND} -E copy ${A_PACKAGE_DIR}/package.json ${A_PACKAGE_DIR}/package-lock.json ${dir}
    COMMAND ${KONTAKT_NPM} ci --no-audit --no-fund --ignore-scripts --loglevel=error
    # npm keeps the packages' own old mtimes; touch so the build sees its outputs as new.
    COMMAND ${CMAKE_COMMAND} -E touch ${outputs}
    WORKING_DIRECTORY ${dir}
    DEPENDS ${A_PACKAGE_DIR}/package.json ${A_PACKAGE_DIR}/package-lock.json
    COMMENT "npm ci: ${A_PACKAGE_DIR}/package-lock.json")
  add_custom_target(${A_TARGET} ALL DEPENDS ${outputs})
  set(${A_OUT_DIR} ${dir} PARENT_SCOPE)
endfunction()
