#!/bin/bash
# Allwmake's build (configureAndBuild of etc/AllwmakeFunctions) keeps the whole compiler output
# in build.log and shows the terminal a line per 10 % of the build: neither minutes of silence
# nor every compiler line in a CI log. A failing build still fails, showing its error.
. "$SPHCAST_TEST_TOOLS"
. "$(cd "$(dirname "${BASH_SOURCE[0]}")/../../etc" && pwd)/AllwmakeFunctions"
mkdir -p "$scratch/project"
cd "$scratch/project"
cat > CMakeLists.txt <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(progress LANGUAGES NONE)
foreach(i RANGE 1 30)
  add_custom_command(OUTPUT step${i} COMMAND ${CMAKE_COMMAND} -E touch step${i}
                     COMMENT "compiling step ${i}")
  list(APPEND steps step${i})
endforeach()
add_custom_target(steps ALL DEPENDS ${steps})
CMAKE
configureAndBuild > out.log 2> err.log || fail "configureAndBuild: $(cat err.log)"
grep -q "compiling step 30" build.log || fail "build.log lacks the build output"
! grep -q "compiling" out.log || fail "the compiler lines went to the terminal: $(cat out.log)"
lines=$(grep -c '^   built  *[0-9]* %$' out.log)
[ "$lines" -ge 5 ] && [ "$lines" -le 11 ] || fail "$lines progress lines: $(cat out.log)"
grep -q '^   built 100 %$' out.log || fail "no 100 %: $(cat out.log)"

cat >> CMakeLists.txt <<'CMAKE'
add_custom_target(broken ALL COMMAND ${CMAKE_COMMAND} -E false DEPENDS steps)
CMAKE
if configureAndBuild > out.log 2> err.log; then fail "a failing build succeeded"; fi
grep -q "Error: the build failed; the whole log is build.log" err.log ||
    fail "no failure message: $(cat err.log)"
pass "the build shows $lines progress lines, keeps its output in build.log and still fails"
