# Every command README.md's code blocks show and every `xval ...` example
# of every --help runs (label `cross`: the examples use POV-Ray and
# Blender). Nothing is skipped silently: a command this test does not run
# is in EXCLUDED below with the reason, and any other line it cannot place
# fails it.
#
# Where: a fresh folder WORK holding what a checkout holds at the paths the
# README uses: build/renderer/xval (a link to XVAL) and reference/ (a
# folder of links to the checkout's specs, models, textures, tolerance
# file and golden images, and a scenes/ folder of links to each scene
# file, so a command that writes into reference/scenes replaces a link
# here, never a checkout file).
#
# How a synopsis line becomes a command (fixed):
#   1. a `# ...` comment is dropped; a line ending in `\` is joined with the
#      next;
#   2. `[...]` groups (optional parts) are dropped, each option in them
#      checked to be in the subcommand's --help; a group that is a
#      placeholder, `[SCENES or DIRS...]`, is kept as SCENES;
#   3. `a|b|c` after an option takes the first (`--renderer povray`); as a
#      word of its own it gives one command per alternative (`export pov`,
#      `export gltf`; `golden update`, `golden check`);
#   4. the placeholders are replaced (PLACEHOLDERS below: SCENE.json is a
#      1-scene set made from docs/examples/first_scene, the outputs go to
#      WORK/out/...), and SUBCOMMAND by every subcommand;
#   5. heavy commands get the fixed LIGHTER options below (one extremes
#      case at 32 px, a quick 32 px trade-off, one bench frame and run).
# Each runs in WORK and must exit 0 (the documented success: the 1-scene
# set passes with every renderer), never 2 (a usage or other error).
# Help examples: each `xval ...` in backticks with arguments runs the same
# way; each plain mention `xval SUBCOMMAND` must name a subcommand (its
# --help exits 0); `povray scene.ini` runs in the folder `xval export pov`
# wrote, as its help says; a one-word span is a name (golden, scenes), and
# any other span fails the test.
# -DXVAL=... -DREADME=... -DCHECKOUT=... -DWORK=...
cmake_minimum_required(VERSION 3.20)  # IN_LIST, file(ARCHIVE_EXTRACT)
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(documented_commands.cmake XVAL README CHECKOUT WORK)

# Commands not run here, each with the reason (matched at the start of the
# joined line).
set(EXCLUDED
  "bash scripts/main.sh|the whole main job: installs, builds, renders all reference scenes with every renderer (tens of minutes)"
  "bash scripts/test.sh|installs, builds and runs every test, this one included"
  "scripts/slurm/submit.sh |needs a Slurm cluster (label cluster: tests/cluster)"
  "bash scripts/build.sh && cd build && ctest -L cluster|needs root, installs Slurm (label cluster)")
# The README's "Your first scene" lines run in first_scene.cmake, as written.
set(FIRST_SCENE_PREFIX "build/renderer/xval render docs/examples/first_scene/|build/renderer/xval crosscheck docs/examples/first_scene/|build/renderer/xval validate docs/examples/first_scene")

set(O ${WORK}/out)
# subcommand:placeholder -> value; then placeholder -> value.
set(PLACEHOLDERS
  "SCENE.json=${WORK}/set/scenes/first_scene.json"
  "SCENE=${WORK}/set/scenes/first_scene.json"
  "SCENES=${WORK}/set/scenes"
  "SPEC.json=reference/specs/fig1.json"
  "render:OUT.exr=${O}/render_#.exr"
  "A.exr=${O}/render_0.exr" "B.exr=${O}/render_1.exr"
  "export:DIR/=${O}/export_#" "crosscheck:DIR/=${O}/crosscheck" "generate:DIR/=${O}/generated"
  "tradeoff:DIR/=${O}/tradeoff" "tradeoff:DIR=${O}/tradeoff_help" "extremes:DIR/=${O}/extremes"
  "extremes:DIR=${O}/extremes_help" "extremes:/tmp/x=${O}/extremes_tmp"
  "validate:results/<run>/=${O}/validation" "validate:OUT=${O}/validation"
  "validate:OUT/jobs.json=${O}/validation/jobs.json" "validate:K=0" "validate:LIST=0"
  "validate:DIR/scenes=${WORK}/unpacked/set/scenes"
  "report:OUT/results.json=${O}/validation/results.json"
  "pack:SET=${WORK}/set" "pack:FILE.tar.gz=${O}/set.tar.gz" "pack:DIR=${WORK}/unpacked/set")
set(LIGHTER
  "extremes=--only specular_n1e6 --size 32"
  "tradeoff=--quick --frames 1 --max-seconds 0.1 --width 32 --height 32"
  "bench=--renderers reference,povray")
# Option values replaced in heavy commands (subcommand:option=value).
set(VALUES "bench:--frames=1" "bench:--runs=1")

# --- the fresh folder ---------------------------------------------------
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/build/renderer ${WORK}/reference/scenes ${O} ${WORK}/set/scenes ${WORK}/set/models
     ${WORK}/set/textures ${WORK}/unpacked)
file(CREATE_LINK ${XVAL} ${WORK}/build/renderer/xval SYMBOLIC)
foreach(f specs models textures golden tolerances.json)
  file(CREATE_LINK ${CHECKOUT}/reference/${f} ${WORK}/reference/${f} SYMBOLIC)
endforeach()
file(GLOB scenes ${CHECKOUT}/reference/scenes/*.json)
foreach(f IN LISTS scenes)
  get_filename_component(n ${f} NAME)
  file(CREATE_LINK ${f} ${WORK}/reference/scenes/${n} SYMBOLIC)
endforeach()
# The 1-scene set: the first scene with its files beside it.
file(READ ${CHECKOUT}/docs/examples/first_scene/first_scene.json s)
string(REPLACE "../../../reference/" "../" s "${s}")
file(WRITE ${WORK}/set/scenes/first_scene.json "${s}")
file(COPY ${CHECKOUT}/reference/models/BoxTextured.glb DESTINATION ${WORK}/set/models)
file(COPY ${CHECKOUT}/reference/textures/noise16_37x23_rgba.png DESTINATION ${WORK}/set/textures)

# --- helpers ------------------------------------------------------------
function(lookup out sub key)
  foreach(entry IN LISTS PLACEHOLDERS)
    if(entry MATCHES "^${sub}:(.*)=(.*)$" AND CMAKE_MATCH_1 STREQUAL key)
      set(${out} "${CMAKE_MATCH_2}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  foreach(entry IN LISTS PLACEHOLDERS)
    if(NOT entry MATCHES "^[a-z]+:" AND entry MATCHES "^([^=]*)=(.*)$" AND CMAKE_MATCH_1 STREQUAL key)
      set(${out} "${CMAKE_MATCH_2}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  set(${out} "${key}" PARENT_SCOPE)
endfunction()

set(ran 0)
set(counter_render 0)
set(counter_export 0)
# Runs one xval command line (words separated by spaces, no brackets, no
# alternatives left), placeholders replaced.
function(run_xval_line line)
  separate_arguments(words UNIX_COMMAND "${line}")
  list(POP_FRONT words exe)
  list(GET words 0 sub)
  set(args "")
  set(prev "")
  foreach(w IN LISTS words)
    lookup(v ${sub} "${w}")
    foreach(entry IN LISTS VALUES)
      if(entry MATCHES "^${sub}:([^=]*)=(.*)$" AND CMAKE_MATCH_1 STREQUAL prev)
        set(v "${CMAKE_MATCH_2}")
      endif()
    endforeach()
    if(v MATCHES "#")
      string(REPLACE "#" "${counter_${sub}}" v "${v}")
    endif()
    list(APPEND args "${v}")
    set(prev "${w}")
  endforeach()
  if(DEFINED counter_${sub})
    math(EXPR c "${counter_${sub}} + 1")
    set(counter_${sub} ${c} PARENT_SCOPE)
  endif()
  foreach(entry IN LISTS LIGHTER)
    if(entry MATCHES "^${sub}=(.*)$")
      separate_arguments(extra UNIX_COMMAND "${CMAKE_MATCH_1}")
      list(APPEND args ${extra})
    endif()
  endforeach()
  if(sub STREQUAL "pack" AND "--verify" IN_LIST args)
    # What --verify checks: the archive `pack SET -o FILE.tar.gz` wrote, unpacked.
    file(ARCHIVE_EXTRACT INPUT ${O}/set.tar.gz DESTINATION ${WORK}/unpacked)
  endif()
  list(JOIN args " " shown)
  message("[${line}] -> xval ${shown}")
  execute_process(COMMAND ${exe} ${args} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "\"${line}\" (run as xval ${shown}): exit ${rc}, expected 0\n${out}\n${err}")
  endif()
  math(EXPR n "${ran} + 1")
  set(ran ${n} PARENT_SCOPE)
endfunction()

# Help text of a subcommand ("" for the top level), for the option check.
function(help_of out sub)
  separate_arguments(s UNIX_COMMAND "${sub}")
  execute_process(COMMAND ${XVAL} ${s} --help RESULT_VARIABLE rc OUTPUT_VARIABLE h ERROR_VARIABLE e)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "xval ${sub} --help: exit ${rc}: ${e}")
  endif()
  set(${out} "${h}" PARENT_SCOPE)
endfunction()

# The subcommands, from the top-level help.
help_of(top "")
string(FIND "${top}" "Subcommands:" at)
string(SUBSTRING "${top}" ${at} -1 subs_text)
string(REGEX MATCHALL "\n  [a-z]+" subs "${subs_text}")
list(TRANSFORM subs STRIP)

# Expands a synopsis (steps 2-4) and runs each resulting command.
function(run_synopsis line)
  # 2. optional groups: check their options exist, then drop them.
  separate_arguments(w0 UNIX_COMMAND "${line}")
  list(GET w0 1 sub)
  if(sub STREQUAL "golden")
    set(sub_help "golden update")
  else()
    set(sub_help "${sub}")
  endif()
  string(REGEX MATCHALL "\\[[^]]*\\]" groups "${line}")
  if(NOT sub STREQUAL "SUBCOMMAND")
    help_of(h "${sub_help}")
    foreach(g IN LISTS groups)
      string(REGEX MATCHALL "--[a-z0-9-]+" opts "${g}")
      foreach(opt IN LISTS opts)
        string(FIND "${h}" "${opt}" found)
        if(found EQUAL -1)
          message(FATAL_ERROR "\"${line}\": ${opt} is not in `xval ${sub_help} --help`")
        endif()
      endforeach()
    endforeach()
  endif()
  # A group that is a placeholder ([SCENES or DIRS...]) keeps it: without
  # scenes, validate and golden would take the toolkit's whole set.
  string(REGEX REPLACE "\\[([A-Z]+)[^]]*\\]" "\\1" line "${line}")
  string(REGEX REPLACE "\\[[^]]*\\]" "" line "${line}")
  string(REGEX REPLACE " +" " " line "${line}")
  string(STRIP "${line}" line)
  # 3. alternatives.
  separate_arguments(words UNIX_COMMAND "${line}")
  set(variants "")
  set(prev "")
  set(split_at -1)
  set(i 0)
  foreach(w IN LISTS words)
    if(w MATCHES "\\|")
      string(REPLACE "|" ";" alts "${w}")
      if(prev MATCHES "^-")
        list(GET alts 0 first)
        list(REMOVE_AT words ${i})
        list(INSERT words ${i} "${first}")
      else()
        set(split_at ${i})
        set(split_alts "${alts}")
      endif()
    endif()
    set(prev "${w}")
    math(EXPR i "${i} + 1")
  endforeach()
  if(sub STREQUAL "SUBCOMMAND")
    set(split_at 1)
    set(split_alts "${subs}")
  endif()
  if(split_at EQUAL -1)
    list(JOIN words " " l)
    run_xval_line("${l}")
  else()
    foreach(alt IN LISTS split_alts)
      set(ws "${words}")
      list(REMOVE_AT ws ${split_at})
      list(INSERT ws ${split_at} "${alt}")
      list(JOIN ws " " l)
      run_xval_line("${l}")
    endforeach()
  endif()
  set(ran ${ran} PARENT_SCOPE)
  set(counter_render ${counter_render} PARENT_SCOPE)
  set(counter_export ${counter_export} PARENT_SCOPE)
endfunction()

# --- README.md's code blocks (indented four spaces) -----------------------
file(READ ${README} readme)
# (As list elements: a trailing backslash would escape the separator, and
# CMake splits no list inside unbalanced brackets; both are stood in for.)
string(REPLACE "\\" "<bs>" readme "${readme}")
string(REPLACE ";" "\\;" readme "${readme}")
string(REPLACE "[" "<lb>" readme "${readme}")
string(REPLACE "]" "<rb>" readme "${readme}")
string(REPLACE "\n" ";" lines "${readme}")
set(joined "")
set(commands "")
foreach(line IN LISTS lines)
  string(REPLACE "<lb>" "[" line "${line}")
  string(REPLACE "<rb>" "]" line "${line}")
  if(NOT line MATCHES "^    ")
    continue()
  endif()
  string(SUBSTRING "${line}" 4 -1 line)
  string(STRIP "${line}" line)
  if(line MATCHES "<bs>$")
    string(REGEX REPLACE "<bs>$" "" line "${line}")
    string(APPEND joined "${line} ")
    continue()
  endif()
  set(line "${joined}${line}")
  set(joined "")
  string(REPLACE "<bs>" "\\" line "${line}")
  if(line MATCHES "^[{}\"]|^],?$")
    continue()  # the first scene's JSON (checked by first_scene.cmake)
  endif()
  string(REGEX REPLACE " +#.*$" "" line "${line}")
  string(REPLACE "[" "<lb>" line "${line}")
  string(REPLACE "]" "<rb>" line "${line}")
  list(APPEND commands "${line}")
endforeach()

foreach(line IN LISTS commands)
  string(REPLACE "<lb>" "[" line "${line}")
  string(REPLACE "<rb>" "]" line "${line}")
  set(excluded "")
  foreach(entry IN LISTS EXCLUDED)
    string(REGEX MATCH "^[^|]*" prefix "${entry}")
    string(FIND "${line}" "${prefix}" at)
    if(at EQUAL 0)
      set(excluded "${entry}")
    endif()
  endforeach()
  string(REPLACE "|" ";" first_prefixes "${FIRST_SCENE_PREFIX}")
  foreach(prefix IN LISTS first_prefixes)
    string(FIND "${line}" "${prefix}" at)
    if(at EQUAL 0)
      set(excluded "first scene|run as written by first_scene.cmake")
    endif()
  endforeach()
  if(excluded)
    message("not run: \"${line}\": ${excluded}")
  elseif(line MATCHES "^build/renderer/xval ")
    run_synopsis("${line}")
  else()
    message(FATAL_ERROR "README.md: \"${line}\": neither an xval command nor in EXCLUDED (with a reason)")
  endif()
endforeach()

# --- --help examples ------------------------------------------------------
set(helps "")
foreach(s "" ${subs} "golden update" "golden check")
  help_of(h "${s}")
  string(APPEND helps "${h}\n")
endforeach()
string(REGEX MATCHALL "`[^`]*`" spans "${helps}")
list(REMOVE_DUPLICATES spans)
string(REGEX MATCHALL "xval [a-z]+( update| check)?" mentions "${helps}")
list(REMOVE_DUPLICATES mentions)
foreach(m IN LISTS mentions)
  string(REPLACE "xval " "" m "${m}")
  help_of(h "${m}")  # fails unless it is a subcommand
endforeach()
foreach(span IN LISTS spans)
  string(REPLACE "`" "" span "${span}")
  if(span MATCHES "^xval [a-z]+( update| check)?$")
    continue()  # a mention of a subcommand, checked above
  elseif(span MATCHES "^xval ")
    run_synopsis("build/renderer/${span}")
  elseif(span STREQUAL "povray scene.ini")
    message("[povray scene.ini] in ${O}/export_0")
    execute_process(COMMAND povray scene.ini WORKING_DIRECTORY ${O}/export_0 RESULT_VARIABLE rc
                    OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "`povray scene.ini` (xval export's help) in ${O}/export_0: exit ${rc}\n${err}")
    endif()
    math(EXPR ran "${ran} + 1")
  elseif(span MATCHES "^[A-Za-z0-9_.-]+$")
    continue()  # one word: a renderer's, folder's or field's name (golden, scenes), not a command
  else()
    message(FATAL_ERROR "--help: `${span}`: neither a command this test runs nor one word (a name)")
  endif()
endforeach()
message("ran ${ran} documented commands")
