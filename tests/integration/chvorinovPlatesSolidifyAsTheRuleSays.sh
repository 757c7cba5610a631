#!/bin/bash
# tutorials/validation/chvorinovPlates at dx = 0.5 mm (152, 312 and 632 particles; about 12 s):
# three AC4CH plates 10, 20 and 40 mm thick cast at 970 K between molds held at 300 K, no flow.
# compareWithReference --check: the exponent of t_s = B (V/A)^n through the three within 0.1 of
# the 2 of faces held at a fixed temperature (measured 1.966), each plate's t_s within 10 % of
# the finite-difference enthalpy solution and its solidification-time map within 10 % RMS
# (measured +6.7 / +3.3 / +1.8 % and 6.7 / 2.9 / 1.2 %). The error is first order in dx / D
# (the held surface on the first held layer's centres): at dx = 1 mm the 10 mm plate is 13.5 %
# late and fails the bound, as it should; a held surface half a layer off would too.
. "$SPHCAST_TEST_TOOLS"
findVtkPython
runValidationTutorial chvorinovPlates 0.5
cat log.compareWithReference
"$python" compareWithReference --check > /dev/null || fail "the plates against the reference"
pass "Chvorinov's rule: three plates' solidification times and maps against the enthalpy solution"
