# mk/asn.mk: the paper's Associative Search Network, reconstructed (issue 20):
# blocks 1070-1078, docs/learning.md.
#   make asn-runs    50 trials learning (twice: the same CSV), with Rate 0, and
#                    with four other noise seeds, by scripted runs, in build/asn/
#                    (trials.csv, transcripts, traces); the model checked at
#                    every step; figures in docs/img/asn-*.png
#   make bench-asn   one learning step's cost: instructions, KDF11-A time
#                    (part of make bench)
asn-runs: $(BUILD)/kernel.lda $(BUILD)/pdp11 $(BUILD)/robot.dsk venv  ## the ASN learning 50 trials (and controls), its figures (docs/learning.md)
	@$(PY) -m harness.figures.asn_runs $(BUILD)/asn --figures docs/img

bench-asn: $(BUILD)/kernel.lda $(BUILD)/pdp11 $(BUILD)/robot.dsk venv  ## one ASN learning step's cost: instructions, KDF11-A time
	@$(PY) -m harness.bench.asn_bench

BENCHES += bench-asn
.PHONY: asn-runs bench-asn
