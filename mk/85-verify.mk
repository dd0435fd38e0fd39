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
paper/report.html paper/supplement.html: $(VERIFY_STAMP)

# Every unit of the store recomputed under the current code and compared with the stored rows
# (--verify at every stored level, the registry's arguments): hours at paper scale (the plan
# prices it: make plan PROFILE=paper), for a machine lent for the purpose; its log goes to
# results/verify_full.log.  make test recomputes the coarse units and a sample of the finer ones.
.PHONY: verify-store-full
verify-store-full: build
	@$(BUILD)/gpm study --store-rows | \
	while IFS="$$(printf '\t')" read -r _s file program args census _c _sl; do \
	  [ "$$args" = - ] && args=""; [ "$$census" = - ] && census=""; \
	  echo "== $$(date -u +%FT%TZ) $$file"; \
	  out=$$(nice -n 19 $(BUILD)/$$program $$args $$census --profile paper --out $(STORE)/$$file.tsv --verify 2>&1); rc=$$?; \
	  echo "$$out" | grep '\[store\]\|rror'; [ $$rc -eq 0 ] || exit 1; \
	done > results/verify_full.log.tmp 2>&1; rc=$$?; \
	cat results/verify_full.log.tmp; mv results/verify_full.log.tmp results/verify_full.log; exit $$rc
