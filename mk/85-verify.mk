# Verify step (issue 8): before pandoc assembles the report, every figure and data table that
# paper/*.md references must exist and every SVG must draw something; otherwise the build
# stops here with one line per problem (tests/report/verify_report.sh).  The stamp depends
# on everything the report depends on, so it reruns whenever a source or result changes.
# The figures must also keep the figure rules (tests/report/figure_rules.sh: no two series
# of a panel told apart by colour alone, at most six series a panel).
VERIFY_STAMP := $(DATA)/.report_verified

$(VERIFY_STAMP): tests/report/verify_report.sh tests/report/figure_rules.sh $(sort $(wildcard paper/[0-9][0-9]-*.md)) $(DATAFILES) $(FIGFILES)
	sh tests/report/verify_report.sh paper $(DATA) .
	bash tests/report/figure_rules.sh figures/out
	@touch $@

.PHONY: verify-report
verify-report: $(VERIFY_STAMP)

# Extra prerequisite of the paper and the supplement (the Makefile's pandoc recipe names its
# inputs itself).
paper/report.html paper/supplement.html docs/companion.html: $(VERIFY_STAMP)

# Every unit of the store recomputed under the current code and compared with the stored rows,
# level by level, cheapest first, resumably: one sealed line per (file, level) in
# results/paper/verified.log, so a rerun continues where it stopped (tests/store/
# verify_store_full.sh; VERIFY_FLAGS=--dry-run prices it, --budget SECONDS bounds a run,
# --until TIME takes no job that would end after TIME,
# --jobs 2 runs two levels at a time, one thread each on two cores; a level above an hour goes
# in parts, --split-above SECONDS; with lanes, jobs of 2.5 h or more on one thread run last on
# all the cores, --wide-above SECONDS).
# make test recomputes the coarse units and a sample of the finer ones.
.PHONY: verify-store-full
verify-store-full: build
	nice -n 19 bash tests/store/verify_store_full.sh $(BUILD) $(STORE) $(VERIFY_FLAGS)

# The same run in the background, from frozen copies of the programs and scripts, leaving the
# tree clean (tests/store/verify_background.sh): verify-store-bg starts it (VERIFY_FLAGS as
# above, e.g. "--cheap --jobs 2"), verify-store-merge appends its new lines to verified.log (to
# commit as they land), verify-store-status shows it, verify-store-drain lets it end after the
# jobs it holds.
.PHONY: verify-store-bg verify-store-merge verify-store-status verify-store-drain
verify-store-bg: build
	bash tests/store/verify_background.sh start $(BUILD) $(STORE) $(VERIFY_FLAGS)
verify-store-merge:
	bash tests/store/verify_background.sh merge $(STORE)
verify-store-status:
	bash tests/store/verify_background.sh status
verify-store-drain:
	bash tests/store/verify_background.sh drain
