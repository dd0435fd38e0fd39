# Paper scale from the committed result store (results/paper), for every profile: the
# documents' rates computed from the stored rows (no study is run), the provenance of those
# rows, and the verdict counts.  A fresh clone's `make report` shows them at once.
STORE_FILES := $(wildcard $(STORE)/*.tsv)
DATAFILES += $(DATA)/store_rates.tsv $(DATA)/store_summary.tsv $(DATA)/store_score.tsv \
             $(DATA)/checked_reasons.tsv $(DATA)/setup_identification.tsv $(DATA)/open_causes.tsv \
             $(DATA)/store_figure_files.tsv

# One judging pass over the store (gpm store-rates, src/gpm/studies/judge/), from one read of
# it (judge/snapshot.hpp): the reasons for differing rates, each with the diagnostic that
# checks it (checked_reasons.hpp; also one row per mechanism, the chapter's short table), the
# two scoreboards (as printed, as identified), the fingerprint evidence that identifies
# Chapter 4's set-up (setup_identification.tsv; paper/04-setup-rule.md), the open rates grouped
# by cause, the store file each per-reading figure draws (store_figure_files.tsv), the
# documents' open set-up questions with the store's evidence (decisions.hpp) and the heat
# rates at every pair of stored levels with whether they approach the theory's (the thesis'
# conjecture: rate_levels.hpp).
DATAFILES += $(DATA)/checked_reasons_by_mechanism.tsv $(DATA)/decisions.tsv \
             $(DATA)/rate_levels.tsv $(DATA)/rate_levels_findings.tsv \
             $(DATA)/error_constants.tsv $(DATA)/error_constant_findings.tsv
$(DATA)/store_rates.tsv: $(STORE_FILES) $(BUILD)/gpm $(wildcard tables/published/*.tsv) \
    $(wildcard results/diagnostics/*.tsv)
	@mkdir -p $(DATA)
	$(BUILD)/gpm store-rates --store $(STORE) --published tables/published \
	  --reasons $(DATA)/checked_reasons.tsv --reasons-by-mechanism $(DATA)/checked_reasons_by_mechanism.tsv \
	  --out $@ --summary $(DATA)/store_summary.tsv --score $(DATA)/store_score.tsv \
	  --ident $(DATA)/setup_identification.tsv --causes $(DATA)/open_causes.tsv \
	  --figure-files $(DATA)/store_figure_files.tsv \
	  --diagnostics results/diagnostics --decisions $(DATA)/decisions.tsv \
	  --rate-levels $(DATA)/rate_levels.tsv --findings $(DATA)/rate_levels_findings.tsv \
	  --constants $(DATA)/error_constants.tsv --constant-findings $(DATA)/error_constant_findings.tsv
$(DATA)/error_constants.tsv $(DATA)/error_constant_findings.tsv \
$(DATA)/store_summary.tsv $(DATA)/store_score.tsv $(DATA)/setup_identification.tsv $(DATA)/open_causes.tsv \
  $(DATA)/store_figure_files.tsv $(DATA)/decisions.tsv $(DATA)/rate_levels.tsv $(DATA)/rate_levels_findings.tsv \
  $(DATA)/checked_reasons.tsv $(DATA)/checked_reasons_by_mechanism.tsv: $(DATA)/store_rates.tsv ;

FIGFILES += $(FIGOUT)/thesis_rate_levels.svg
$(FIGOUT)/thesis_rate_levels.svg: figures/thesis_rate_levels.gp figures/style.gp $(DATA)/rate_levels.tsv
	@mkdir -p $(FIGOUT)
	gnuplot -e "datadir='$(DATA)'; out='$@.tmp'" $< && mv $@.tmp $@

# The predictions written before the runs (results/predictions/error_constants_2e-11.md) beside
# what the store holds now: hit, miss or not run.
DATAFILES += $(DATA)/prediction_outcomes.tsv
$(DATA)/prediction_outcomes.tsv: results/predictions/outcome_error_constants.sh $(STORE_FILES) \
    $(wildcard results/predictions/error_constants/*.tsv)
	@mkdir -p $(DATA)
	bash $< $(STORE) $@

# The error constants against level (judge/error_constants.hpp), beside the one-mode model.
FIGFILES += $(FIGOUT)/thesis_error_constants.svg
$(FIGOUT)/thesis_error_constants.svg: figures/thesis_error_constants.gp figures/style.gp $(DATA)/error_constants.tsv
	@mkdir -p $(FIGOUT)
	gnuplot -e "datadir='$(DATA)'; out='$@.tmp'" $< && mv $@.tmp $@

# The set-up fingerprint drawn: each reading's distance from Table 4.6's theta = 0 rates.
FIGFILES += $(FIGOUT)/setup_fingerprint.svg
$(FIGOUT)/setup_fingerprint.svg: figures/setup_fingerprint.gp figures/style.gp $(DATA)/setup_identification.tsv
	@mkdir -p $(FIGOUT)
	gnuplot -e "datadir='$(DATA)'; out='$@.tmp'" $< && mv $@.tmp $@

# Figures from the store itself (paper scale, whatever the profile).
FIGFILES += $(FIGOUT)/thesis_poisson_volumes.svg
$(FIGOUT)/thesis_poisson_volumes.svg: figures/thesis_poisson_volumes.gp figures/style.gp $(STORE)/thesis_poisson_diagnostic.tsv
	@mkdir -p $(FIGOUT)
	gnuplot -e "datadir='$(DATA)'; storedir='$(STORE)'; out='$@.tmp'" $< && mv $@.tmp $@

# What the store still owes, by the census of every registry store file (each read by its
# program with --census), each missing unit priced by the plan on this machine.
DATAFILES += $(DATA)/store_census.tsv
$(DATA)/store_census.tsv: tables/store_census.sh tables/census_lib.sh $(STORE_FILES) $(BUILD)/gpm $(DATA)/plan_paper.tsv
	@mkdir -p $(DATA)
	bash $< $(BUILD) $(STORE) $(DATA)/plan_paper_summary.tsv $@

# Page one: a verdict per figure and table of the documents (tables/items.tsv), each with the
# number that decides it: paper-scale rates from the store, the other checks from this run
# (gpm verdicts, the rules of src/gpm/studies/judge/page_verdicts.hpp).
DATAFILES += $(DATA)/verdicts.tsv
$(DATA)/verdicts.tsv: $(BUILD)/gpm tables/items.tsv $(DATA)/store_score.tsv \
    $(DATA)/koba_sato_cor71.tsv $(DATA)/koba_sato_bounds.tsv $(DATA)/imoto_regularity_cover.tsv \
    $(DATA)/imoto_figs_particles.tsv $(DATA)/core_voronoi.tsv $(DATA)/core_weights.tsv
	@mkdir -p $(DATA)
	$(BUILD)/gpm verdicts --items tables/items.tsv --score $(DATA)/store_score.tsv --data $(DATA) --out $@

# The documents' figures drawn from the store where it holds their levels (the same gnuplot
# scripts, datadir = the store): figures/out/store_<figure>.svg.  A study's figures and their
# rules are the registry's (build/studies.mk; the per-reading ones, Figures 4.8-4.11, in the
# reading the set-up rule identified and in the one printed); the figure of a group of studies
# is here.
FIGFILES += $(FIGOUT)/store_thesis_heat_readings.svg
$(FIGOUT)/store_thesis_heat_readings.svg: $(foreach f,$(STUDY_FILES_heat),$(STORE)/$(f).tsv)
$(FIGOUT)/store_%.svg: figures/%.gp figures/style.gp
	@mkdir -p $(FIGOUT)
	gnuplot -e "datadir='$(STORE)'; $(GNUPLOT_STUDIES); out='$@.tmp'" $< && mv $@.tmp $@

# The units past the documents that issue 40 asks for (tables/beyond.tsv): each priced by the
# plan on this machine, with what the store holds of it (its census at the level).
DATAFILES += $(DATA)/beyond_plan.tsv
$(DATA)/beyond_plan.tsv: tables/beyond_plan.sh tables/census_lib.sh tables/beyond.tsv $(STORE_FILES) $(BUILD)/gpm $(BUILD)/plan $(DATA)/plan.tsv
	@mkdir -p $(DATA)
	bash $< $(BUILD) $(STORE) $(DATA)/plan.tsv $@
