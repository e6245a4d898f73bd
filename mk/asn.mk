# mk/asn.mk: the paper's Associative Search Network, reconstructed (issue 20):
# blocks 1070-1077, docs/learning.md.
#   make asn-runs    50 trials learning (and again, and with Rate 0) by scripted
#                    runs, in build/asn/ (trials.csv, transcripts, traces), the
#                    model checked at every step, figures in docs/img/asn-*.png
asn-runs: $(BUILD)/kernel.lda $(BUILD)/pdp11 $(BUILD)/robot.dsk venv
	@$(PY) -m harness.bench.asn_runs $(BUILD)/asn --figures docs/img

.PHONY: asn-runs
