# Issue 7: what this machine can do (bench_limit) and the kernels measured against it
# (bench_kernel, bench_laplacian); the report's performance section (paper/60-performance.md).
#
# Two homes for the same measurements:
#  * data/<profile>/bench_*.tsv — made with the report, so the section always has its
#    tables.  Quick profile: fewer repeats, a subset of kernel variants (the steps of the
#    section's table) and the Laplacian at 2^-6 and 2^-7 only (assembling 2^-8 alone
#    costs about a minute), about a minute in all on an idle machine.  Paper profile: the
#    full benchmarks.
#  * data/bench/ — `make bench-all` (what `make bench` should run): full benchmarks, the
#    measured limit first, every kernel variant with its fraction of the limit.
ifeq ($(PROFILE),quick)
BENCH_LIMIT_ARGS     := --repeats 3 --lanes 1e8 --mib 256
BENCH_KERNEL_ARGS    := --repeats 2 --variants plain,fused1_cells1,fused1,fused1_nodiv,fused1_block,separate9,fused9,study:imoto9,study:thesis4_1,study:thesis4_2,study:thesis4_3
BENCH_LAPLACIAN_ARGS := --repeats 3 --dx 2^-6,2^-7
else
BENCH_LIMIT_ARGS     :=
BENCH_KERNEL_ARGS    :=
BENCH_LAPLACIAN_ARGS :=
endif

DATAFILES += $(DATA)/bench_limit.tsv $(DATA)/bench_kernel.tsv $(DATA)/bench_laplacian.tsv

$(DATA)/bench_limit.tsv: $(BUILD)/bench_limit
	$< $(BENCH_LIMIT_ARGS) --profile $(PROFILE) --out $@

$(DATA)/bench_kernel.tsv: $(BUILD)/bench_kernel $(DATA)/bench_limit.tsv
	$< $(BENCH_KERNEL_ARGS) --profile $(PROFILE) --limit $(DATA)/bench_limit.tsv --out $@

$(DATA)/bench_laplacian.tsv: $(BUILD)/bench_laplacian $(DATA)/bench_limit.tsv
	$< $(BENCH_LAPLACIAN_ARGS) --profile $(PROFILE) --limit $(DATA)/bench_limit.tsv --out $@

# The full benchmarks in one run: limit, every kernel variant (pairs/s, candidate pairs/s,
# fraction of the limit), the Laplacian application at 2^-6 … 2^-8.
.PHONY: bench-all bench-limit
bench-limit: $(BUILD)/bench_limit
	$(BUILD)/bench_limit --out data/bench/limit.tsv

bench-all: bench-limit $(BUILD)/bench_kernel $(BUILD)/bench_laplacian
	$(BUILD)/bench_kernel --limit data/bench/limit.tsv --out data/bench/kernel.tsv
	$(BUILD)/bench_laplacian --limit data/bench/limit.tsv --out data/bench/laplacian.tsv
