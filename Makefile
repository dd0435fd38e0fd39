# gpm-repro — two commands do everything on a fresh Debian 12 machine (as root):
#   make report   install what is missing, build, run the studies, plot, assemble the report
#   make test     install what is missing, build, run the Catch2 suite through ctest
# Other targets: make figures, make tables, make pdf, make bench, make plan, make clean, make deps, make build.
# PROFILE=quick (default, minutes) or PROFILE=paper (the documents' exact resolutions, hours).

# Every stage reads and prints numbers with '.' whatever the user's locale (awk, printf, sort).
export LC_ALL := C

PROFILE ?= quick
BUILD   ?= build
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
DATA    := data/$(PROFILE)
FIGOUT  := figures/out
TABOUT  := tables/out

ifneq ($(PROFILE),quick)
ifneq ($(PROFILE),paper)
$(error unknown PROFILE '$(PROFILE)'; valid: quick, paper)
endif
endif

# The paper profile's study files live in the committed result store results/paper/ (see its
# README): a study's rule writes its --out there (store_out), so a paper run resumes from every
# committed unit and its finished units land where git sees them, then links data/paper/<file>
# to it (store_link) for the figures and tables that read data/paper.  Everything derived (rate
# tables, side outputs, diagnostics) is written into data/paper itself, a plain folder: the
# store holds sealed study files only (the programs refuse any other output there).  An older
# checkout's data/paper was one link to the whole store; it is replaced by the folder.
ifeq ($(PROFILE),paper)
STORE_LINK := $(shell mkdir -p data results/paper; \
  if [ -L data/paper ]; then rm data/paper; fi; mkdir -p data/paper && echo ok)
ifneq ($(STORE_LINK),ok)
$(error cannot make the folder data/paper)
endif
store_out = results/paper/$(notdir $(1))
store_link = @ln -sfn ../../results/paper/$(notdir $(1)) $(1)
else
store_out = $(1)
store_link =
endif

# Debian packages the project needs (compilers and their cache, libraries, plotting, report).
PACKAGES := build-essential cmake git pkg-config libeigen3-dev libcgal-dev libgmp-dev \
            libmpfr-dev libboost-dev libgsl-dev libglpk-dev libfftw3-dev glpk-utils catch2 gnuplot-nox pandoc \
            chromium poppler-utils python3 ccache

.PHONY: all report pdf test test-paper bench plan deps build data figures figures-all tables clean help

all: report

help:
	@sed -n '1,7p' Makefile

# In the paper profile a study first re-checks its coarse units against the stored rows
# (results/paper/README.md): when the code changed but its numbers did not, the rows of the
# older code are carried over instead of being recomputed for hours; when the numbers changed,
# the run that follows recomputes them.  Usage in a recipe, before the study's own command:
#   $(call store_recheck,PROGRAM [ARGS],LEVELS)
store_recheck = $(if $(filter paper,$(PROFILE)),@if [ -f $(call store_out,$@) ]; then $(1) --profile paper --out $(call store_out,$@) \
  --recheck --levels $(2) || echo "recheck: numbers changed; the run recomputes the older rows"; fi)

# --- set-up -----------------------------------------------------------------------------
# Installs only what is missing; a second run costs one dpkg query per package.
deps:
	@missing=""; for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  if [ "$$(id -u)" != 0 ]; then echo "error: packages missing ($$missing) and not root; run as root or install them" >&2; exit 1; fi; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing >/dev/null || exit 1; \
	fi

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

# The build also writes the studies' make rules from the study registry (gpm study --make):
# every list of studies below comes from there, none is typed in mk/.
STUDIES_MK := $(BUILD)/studies.mk
build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)
	$(BUILD)/gpm study --make $(STUDIES_MK)

# --- tests ------------------------------------------------------------------------------
test: build
	cd $(BUILD) && ctest --output-on-failure -j 1

# The [paper] tier alone (also part of make test): the committed store's rates against the
# published ones (tests/paper/check_verdicts.sh).
test-paper: build
	bash tests/paper/check_verdicts.sh $(BUILD) .

# --- studies, figures, report sections -------------------------------------------------
# The studies' data and rate-table rules, and the lists STUDIES_<group>, STUDY_FILES, … are
# generated from the study registry (src/gpm/studies/define/registry.cpp) into build/studies.mk by
# `make build`; mk/*.mk add what else each part of the report needs (figures, diagnostics),
# appending to DATAFILES and FIGFILES.  Adding a study: docs/reference.md, "How to add".
# A data file is rebuilt only when its program changed (make's timestamps); inside a
# program, levels already computed with the same parameters are read back, not redone.
DATAFILES :=
FIGFILES :=
# The committed result store (paper profile): set before studies.mk, whose rules name it.
STORE := results/paper
, := ,
# Goals that need no study rule may run before the first build; any other needs them.
ifeq ($(wildcard $(STUDIES_MK)),)
ifneq ($(filter-out all report pdf figures tables test test-paper bench plan deps build clean help,$(or $(MAKECMDGOALS),all)),)
$(error $(STUDIES_MK) is missing: run `make build` first (it writes the studies' make rules))
endif
else
include $(STUDIES_MK)
endif
include $(sort $(wildcard mk/*.mk))

# Figures: gnuplot scripts read data/<profile>, write figures/out/<name>.svg.  A figure that
# draws a group of studies takes its list from the registry (build/studies.mk), not typed.
GNUPLOT_STUDIES = heat_studies='$(STUDIES_heat)'
$(FIGOUT)/%.svg:
	@mkdir -p $(FIGOUT)
	gnuplot -e "datadir='$(DATA)'; $(GNUPLOT_STUDIES); out='$@.tmp'" $< && mv $@.tmp $@

data: $(DATAFILES)
figures-all: $(FIGFILES)

# --- report: paper/NN-*.md in name order -----------------------------------------------
REPORT_SOURCES := $(sort $(wildcard paper/[0-9][0-9]-*.md))

# Two documents from the same sources (paper/tsv-tables.lua, metadata part): the paper
# (chapters, page one, a pointer where a long table stood) and its supplement (appendices,
# the long tables, the provenance of every table and figure), each with its own contents.
# The paper's contents list its chapters only (a page saved); the others list sections too.
TOC_DEPTH_paper := 1
TOC_DEPTH_supplement := 2
TOC_DEPTH_docs := 2
REPORT_INPUTS := $(REPORT_SOURCES) paper/tsv-tables.lua paper/style.css $(DATAFILES) $(FIGFILES)
report_html = pandoc --from markdown --to html5 --standalone --mathml --self-contained \
	  --lua-filter paper/tsv-tables.lua --metadata datadir=$(DATA) \
	  --metadata profile=$(PROFILE) --metadata part=$(1) --toc --toc-depth=$(TOC_DEPTH_$(1)) --css paper/style.css \
	  $(REPORT_SOURCES) -o $@.tmp && mv $@.tmp $@

paper/report.html: $(REPORT_INPUTS)
	$(call report_html,paper)
	@echo "report: $@ (profile $(PROFILE))"

paper/supplement.html: $(REPORT_INPUTS)
	$(call report_html,supplement)
	@echo "report: $@ (profile $(PROFILE))"

# The companion, a third document from the same sources: the chapters marked {.docs}
# (performance against this machine's limits, the cost model, the atlas of accuracy against
# cost, the quick profile), which support no reproduction claim; the paper and the
# supplement link to it.
docs/companion.html: $(REPORT_INPUTS)
	$(call report_html,docs)
	@echo "report: $@ (profile $(PROFILE))"

# The printed form: the browser check (figures that load and draw, no table wider than an
# A4 page, every formula in MathML, no text below 8 pt in a figure, no word split in a table
# cell, no raw caret or nan) on the HTML, then Chromium's print to PDF of the same HTML (print
# rules in paper/style.css).  Then no page of the PDF may stay more than 60 % blank unless a
# chapter follows it (tests/report/page_fill.py); BLANK_PAGES_ALLOWED_<part> is a ratchet for
# the pages the current layout still leaves blank before a figure that does not fit: it may
# fall, never rise.
BLANK_PAGES_ALLOWED_report := 0
BLANK_PAGES_ALLOWED_supplement := 1
BLANK_PAGES_ALLOWED_companion := 2
# A part's own check of the printed PDF before it takes its place, beside its blank-page
# allowance: the paper's page one must hold the bottom line (tests/report/page_one.sh).
PAGE_CHECK_report = bash tests/report/page_one.sh $@.tmp &&
PRINT_RULE_INPUTS := paper/style.css tests/report/browser_check.sh tests/report/page_fill.py tests/report/print_pdf.py \
	tests/report/page_one.sh
print_pdf = bash tests/report/browser_check.sh $< && \
	python3 tests/report/print_pdf.py $< $@.tmp && \
	python3 tests/report/page_fill.py --allow $(BLANK_PAGES_ALLOWED_$*) $@.tmp && \
	$(PAGE_CHECK_$*) mv $@.tmp $@ && echo "report: $@ (printed from $<)"
paper/%.pdf: paper/%.html $(PRINT_RULE_INPUTS)
	@$(print_pdf)
docs/%.pdf: docs/%.html $(PRINT_RULE_INPUTS)
	@$(print_pdf)

REPORT_OUTPUTS := paper/report.html paper/report.pdf paper/supplement.html paper/supplement.pdf \
	docs/companion.html docs/companion.pdf
report: build
	$(MAKE) --no-print-directory PROFILE=$(PROFILE) $(REPORT_OUTPUTS)

pdf: build
	$(MAKE) --no-print-directory PROFILE=$(PROFILE) paper/report.pdf paper/supplement.pdf docs/companion.pdf

# make figures: every figure of the report (figures/out/*.svg), after the build.
figures: build
	$(MAKE) --no-print-directory PROFILE=$(PROFILE) figures-all

# make tables: every reproduced table, published beside ours at paper scale (the committed
# store, whatever the profile), as TSV and Markdown in tables/out/ (tables/reproduced_tables.sh).
tables: build
	$(MAKE) --no-print-directory PROFILE=$(PROFILE) $(DATA)/store_rates.tsv
	bash tables/reproduced_tables.sh $(DATA)/store_rates.tsv $(TABOUT)

# --- benchmarks -------------------------------------------------------------------------
# The measured limit (bench_limit), every kernel variant as a fraction of it, and the
# Laplacian application (assembled vs matrix-free): mk/70-bench.mk.
bench: build
	$(MAKE) --no-print-directory BUILD=$(BUILD) bench-all

clean:
	rm -rf $(BUILD) data $(FIGOUT) $(TABOUT) $(REPORT_OUTPUTS)

# --- data files are never deleted -------------------------------------------------------
# make deletes a target whose recipe is interrupted (Ctrl-C) or killed.  A data file here is
# the result store's own (data/paper/<study file> links into results/paper: hours of sealed rows) or a
# file every program writes atomically (temp file, then rename), so an interrupted recipe
# leaves it whole, old or new, and the study resumes from it.  Listed by name: GNU make
# protects a target named in .PRECIOUS, not one a pattern there matches
# (tests/store/make_interrupt.sh).
.PRECIOUS: $(sort $(DATAFILES) $(foreach f,$(STUDY_FILES),$(DATA)/$(f).tsv))
