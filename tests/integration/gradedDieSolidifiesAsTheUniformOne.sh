#!/bin/bash
# tutorials/validation/gradedDie at dx = 3 mm (about 20 s on one thread): a block of AC4CH
# solidifying in the pocket of an iron die that loses heat to the air, conduction only, the die
# particleized at 3 mm and graded (3 mm within 3 layers of the pocket, up to 12 mm).
# compareGraded --check: the graded die at least 3 times fewer particles (measured 3.07), the
# casting solid within 1 % of the uniform die's time (measured -0.67 %), the heat books of both
# closed within 1e-10 (measured 2.6e-13 and 1.1e-13). Without the first-moment correction of the
# graded conduction, or with the coarser particles' exposed area summed at h, the casting is solid
# 1.7 to 1.9 % early at 2 mm (doc/validation.md §3.1).
. "$SPHCAST_TEST_TOOLS"
findVtkPython
runValidationTutorial gradedDie 3
cat log.compareGraded
"$python" compareGraded --check > /dev/null || fail "the graded die against the uniform one"
pass "a graded die: 3 times fewer particles, the casting solid within 1 % of the uniform die's time"
