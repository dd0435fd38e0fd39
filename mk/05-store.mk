# Paper scale from the committed result store (results/paper), for every profile: the
# documents' rates computed from the stored rows (no study is run), the provenance of those
# rows, and the verdict counts.  A fresh clone's `make report` shows them at once.
STORE := results/paper
STORE_FILES := $(wildcard $(STORE)/*.tsv)
DATAFILES += $(DATA)/store_rates.tsv $(DATA)/store_summary.tsv $(DATA)/store_score.tsv \
             $(DATA)/checked_reasons.tsv $(DATA)/setup_identification.tsv

# Reasons for differing rates, each with the diagnostic that checks it against the stored data,
# and the same reasons one row per mechanism with the rows it covers (the chapter's short
# table): gpm checked-reasons, the rules of src/gpm/studies/checked_reasons.hpp.
DATAFILES += $(DATA)/checked_reasons_by_mechanism.tsv
$(DATA)/checked_reasons.tsv: $(STORE_FILES) $(BUILD)/gpm $(wildcard tables/published/thesis_table4_*_long.tsv)
	@mkdir -p $(DATA)
	$(BUILD)/gpm checked-reasons --store $(STORE) --published tables/published --out $@ \
	  --by-mechanism $(DATA)/checked_reasons_by_mechanism.tsv
$(DATA)/checked_reasons_by_mechanism.tsv: $(DATA)/checked_reasons.tsv ;

# The two scoreboards (as printed, as identified) and the fingerprint evidence that identifies
# Chapter 4's set-up (setup_identification.tsv; paper/04-setup-rule.md): gpm store-rates, the
# verdicts of src/gpm/studies/verdicts.hpp.
$(DATA)/store_rates.tsv: $(STORE_FILES) $(BUILD)/gpm $(wildcard tables/published/*.tsv) $(DATA)/checked_reasons.tsv
	@mkdir -p $(DATA)
	$(BUILD)/gpm store-rates --store $(STORE) --published tables/published --checked $(DATA)/checked_reasons.tsv \
	  --out $@ --summary $(DATA)/store_summary.tsv --score $(DATA)/store_score.tsv \
	  --ident $(DATA)/setup_identification.tsv
$(DATA)/store_summary.tsv $(DATA)/store_score.tsv $(DATA)/setup_identification.tsv: $(DATA)/store_rates.tsv ;

# The documents' open set-up questions, with the evidence the stored runs give (every number
# read from the store or computed by the library: gpm decisions, src/gpm/studies/decisions.hpp).
DATAFILES += $(DATA)/decisions.tsv
$(DATA)/decisions.tsv: $(STORE_FILES) $(BUILD)/gpm tables/published/thesis_table4_7_long.tsv \
    tables/published/thesis_table4_4_long.tsv tables/published/imoto_table1.tsv $(DATA)/store_score.tsv
	@mkdir -p $(DATA)
	$(BUILD)/gpm decisions --store $(STORE) --published tables/published --score $(DATA)/store_score.tsv --out $@

# Figures from the store itself (paper scale, whatever the profile).
FIGFILES += $(FIGOUT)/thesis_poisson_volumes.svg
$(FIGOUT)/thesis_poisson_volumes.svg: figures/thesis_poisson_volumes.gp figures/style.gp $(STORE)/thesis_poisson_diagnostic.tsv
	@mkdir -p $(FIGOUT)
	gnuplot -e "datadir='$(DATA)'; storedir='$(STORE)'; out='$@.tmp'" $< && mv $@.tmp $@

# What the store still owes, with the predicted time of each missing level on this machine.
DATAFILES += $(DATA)/store_missing.tsv
$(DATA)/store_missing.tsv: tables/store_missing.sh $(STORE_FILES) $(DATA)/plan_paper.tsv
	@mkdir -p $(DATA)
	bash $< $(STORE) $(DATA)/plan_paper_summary.tsv $@

# Page one: a verdict per figure and table of the documents (tables/items.tsv), each with the
# number that decides it: paper-scale rates from the store, the other checks from this run
# (gpm verdicts, the rules of src/gpm/studies/page_verdicts.hpp).
DATAFILES += $(DATA)/verdicts.tsv
$(DATA)/verdicts.tsv: $(BUILD)/gpm tables/items.tsv $(DATA)/store_score.tsv \
    $(DATA)/koba_sato_cor71.tsv $(DATA)/koba_sato_bounds.tsv $(DATA)/imoto_regularity_cover.tsv \
    $(DATA)/imoto_figs_particles.tsv $(DATA)/core_voronoi.tsv $(DATA)/core_weights.tsv
	@mkdir -p $(DATA)
	$(BUILD)/gpm verdicts --items tables/items.tsv --score $(DATA)/store_score.tsv --data $(DATA) --out $@

# The documents' figures drawn from the store where it holds their levels (the same gnuplot
# scripts, datadir = the store): figures/out/store_<figure>.svg.
STORE_FIGS := thesis_fig4_3 thesis_fig4_5 thesis_fig4_6 thesis_fig4_7 thesis_fig4_8 thesis_fig4_9 thesis_fig4_10 thesis_fig4_11 thesis_heat_readings imoto_fig5
FIGFILES += $(foreach f,$(STORE_FIGS),$(FIGOUT)/store_$(f).svg)
# Figures 4.8-4.11 (Poisson, heat) from the store in two readings of the set-up: the one the
# set-up rule identified (setup_identification.tsv's `identified`, the board the report leads
# with: store_thesis_fig4_N) and the reading as printed (h10, V_i = |Omega_H|/N, dt = T/K:
# store_printed_thesis_fig4_N, for the supplement); figures/store_reading.sh finds the file.
# store_reading_fig FIGURE TABLE READING PREFIX
define store_reading_fig
$$(FIGOUT)/$(4)thesis_fig$(1).svg: figures/thesis_fig$(1).gp figures/style.gp figures/store_reading.sh \
    tables/store_lib.sh $$(DATA)/setup_identification.tsv $$(wildcard $$(STORE)/thesis_table$(2)*.tsv) tables/published/thesis_table$(2)_long.tsv
	bash figures/store_reading.sh $$< $(2) $(3) $$(STORE) $$(DATA)/setup_identification.tsv $$@
endef
STORE_READING_FIGS := 4_8:4_4 4_9:4_5 4_10:4_6 4_11:4_7
$(foreach p,$(STORE_READING_FIGS),$(eval $(call store_reading_fig,$(word 1,$(subst :, ,$(p))),$(word 2,$(subst :, ,$(p))),identified,store_)))
$(foreach p,$(STORE_READING_FIGS),$(eval $(call store_reading_fig,$(word 1,$(subst :, ,$(p))),$(word 2,$(subst :, ,$(p))),h10,store_printed_)))
$(foreach f,9 10 11,$(FIGOUT)/store_thesis_fig4_$(f).svg $(FIGOUT)/store_printed_thesis_fig4_$(f).svg): figures/thesis_heat.gp
FIGFILES += $(foreach p,$(STORE_READING_FIGS),$(FIGOUT)/store_printed_thesis_fig$(word 1,$(subst :, ,$(p))).svg)
$(FIGOUT)/store_thesis_fig4_3.svg: $(STORE)/thesis_table4_1.tsv figures/thesis_errors.gp tables/published/thesis_table4_1_long.tsv
$(FIGOUT)/store_thesis_fig4_5.svg: $(STORE)/thesis_table4_2.tsv figures/thesis_errors.gp tables/published/thesis_table4_2_long.tsv
$(FIGOUT)/store_thesis_fig4_6.svg $(FIGOUT)/store_thesis_fig4_7.svg: $(STORE)/thesis_table4_3.tsv figures/thesis_errors.gp \
    tables/published/thesis_table4_3_long.tsv
$(FIGOUT)/store_thesis_heat_readings.svg: $(foreach f,$(STUDY_FILES_heat),$(STORE)/$(f).tsv)
$(FIGOUT)/store_imoto_fig5.svg: $(STORE)/imoto_fig5_table1.tsv tables/published/imoto_table1.tsv
$(FIGOUT)/store_%.svg: figures/%.gp figures/style.gp
	@mkdir -p $(FIGOUT)
	gnuplot -e "datadir='$(STORE)'; $(GNUPLOT_STUDIES); out='$@.tmp'" $< && mv $@.tmp $@
