#!/bin/bash
# tutorials/validation/chvorinovPlates at dx = 0.5 mm (160, 320 and 640 particles; about 12 s):
# three AC4CH plates 10, 20 and 40 mm thick cast at 970 K between molds held at 300 K, no flow.
# compareWithReference --check: the exponent of t_s = B (V/A)^n through the three within 0.015
# of the 2 of faces held at a fixed temperature (measured 1.994), each plate's t_s within 3 % of
# the finite-difference enthalpy solution and its solidification-time map within 6 % RMS
# (measured +1.7 / +1.1 / +0.9 % and 4.1 / 1.6 / 0.7 %). With the held surface on the held
# layers' centres the 10 mm plate was 6.7 % late, with the harmonic mean of kappa across the
# freezing front 4.7 %: both fail the bounds, as they should.
. "$SPHCAST_TEST_TOOLS"
findVtkPython
runValidationTutorial chvorinovPlates 0.5
cat log.compareWithReference
"$python" compareWithReference --check > /dev/null || fail "the plates against the reference"
pass "Chvorinov's rule: three plates' solidification times and maps against the enthalpy solution"
