# Verify step (issue 8): before pandoc assembles the report, every figure and data table that
# paper/*.md references must exist and every SVG must draw something; otherwise the build
# stops here with one line per problem (tests/report/verify_report.sh).  The stamp depends
# on everything the report depends on, so it reruns whenever a source or result changes.
VERIFY_STAMP := $(DATA)/.report_verified

$(VERIFY_STAMP): tests/report/verify_report.sh $(sort $(wildcard paper/[0-9][0-9]-*.md)) $(DATAFILES) $(FIGFILES)
	sh tests/report/verify_report.sh paper $(DATA) .
	@touch $@

.PHONY: verify-report
verify-report: $(VERIFY_STAMP)

# Extra prerequisite of the report (the Makefile's pandoc recipe names its inputs itself).
paper/report.html: $(VERIFY_STAMP)
