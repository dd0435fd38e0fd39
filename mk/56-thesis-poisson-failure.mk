# Where the discrete Poisson problem fails (issue 5, beyond the thesis): a weight that changes
# sign (cubic spike vs quartic polynomial) and h below the h-connectivity threshold.
# One program writes both data files; the sweep file is made by the same rule.
DATAFILES += $(DATA)/thesis_poisson_failure.tsv $(DATA)/thesis_poisson_failure_h.tsv
FIGFILES  += $(FIGOUT)/thesis_poisson_failure.svg

$(DATA)/thesis_poisson_failure.tsv: $(BUILD)/thesis_poisson_failure
	$< --profile $(PROFILE) --out $@ --out-sweep $(DATA)/thesis_poisson_failure_h.tsv
	@touch $@ $(DATA)/thesis_poisson_failure_h.tsv  # a fully cached rerun leaves the files as they were

$(DATA)/thesis_poisson_failure_h.tsv: $(DATA)/thesis_poisson_failure.tsv

$(FIGOUT)/thesis_poisson_failure.svg: figures/thesis_poisson_failure.gp figures/style.gp \
  $(DATA)/thesis_poisson_failure.tsv $(DATA)/thesis_poisson_failure_h.tsv
