# mk/robot.mk: the appendix blocks on the emulated robot (issue 4).
#   make bench-robot   Interrupt.Servo's KDF11-A cost per tick (idle, moving)
#                      and 1000 LOAD's simulated and host time (part of make bench)
#   make servo-runs    the traces behind docs/servo.md, in build/servo/ (printed
#                      blocks, and with the proposed block 1030), and its figures,
#                      docs/img/{printed,ramp}-*.png
bench-robot: $(BUILD)/kernel.lda $(BUILD)/pdp11 $(BUILD)/robot.dsk venv  ## the servo's cost per tick on the KDF11-A
	@$(PY) -m harness.bench.robot_bench

servo-runs: $(BUILD)/kernel.lda $(BUILD)/pdp11 $(BUILD)/robot.dsk venv  ## the 1983 servo's traces and figures (docs/servo.md)
	@$(PY) -m harness.figures.servo_runs $(BUILD)/servo/printed --figures docs/img/printed
	@$(PY) -m harness.figures.servo_runs $(BUILD)/servo/ramp --block 1030 --then Ramp.Servo \
	    --figures docs/img/ramp

BENCHES += bench-robot
.PHONY: bench-robot servo-runs
