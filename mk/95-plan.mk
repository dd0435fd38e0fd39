# Cost model (issue 7, item 4): the plan of a profile — predicted pair interactions, time and
# peak memory of every modelled study and level (src/gpm/studies/plan/study_plan.hpp) — printed before
# anything runs, and, once the studies have run, the plan beside their measured times.
#
#   make plan PROFILE=paper   calibrate (a few seconds), print and write data/paper/plan*.tsv;
#                             if data files of the profile exist, compare with them
PLAN_STUDY_DATA := $(foreach f,$(STUDY_FILES),$(DATA)/$(f).tsv)

plan: build
	@mkdir -p $(DATA)
	$(BUILD)/plan --profile $(PROFILE) --out $(DATA)/plan.tsv --summary $(DATA)/plan_summary.tsv \
	  --calibration-table $(DATA)/plan_calibration.tsv --heat-matrix $(DATA)/plan_heat_matrix.tsv
	$(BUILD)/plan_vs_actual --plan $(DATA)/plan.tsv --datadir $(DATA) --out $(DATA)/plan_vs_actual.tsv

# For the report: the plan of this profile (calibrated on the spot), the paper profile's plan
# from the same calibration (no study is run for it), and the comparison with this profile's
# data files (rebuilt whenever one of them changes).
DATAFILES += $(DATA)/plan.tsv $(DATA)/plan_paper.tsv $(DATA)/plan_vs_actual.tsv

$(DATA)/plan.tsv: $(BUILD)/plan
	@mkdir -p $(DATA)
	$< --profile $(PROFILE) --out $@ --summary $(DATA)/plan_summary.tsv \
	  --calibration-table $(DATA)/plan_calibration.tsv --quiet

# The paper plan also prices the heat tables' whole reading matrix three ways (each series
# alone, one run per reading, every reading batched in one block stream).
$(DATA)/plan_paper.tsv: $(BUILD)/plan $(DATA)/plan.tsv
	$< --profile paper --calibration $(DATA)/plan.tsv --out $@ \
	  --summary $(DATA)/plan_paper_summary.tsv --heat-matrix $(DATA)/plan_paper_heat_matrix.tsv --quiet

$(DATA)/plan_vs_actual.tsv: $(BUILD)/plan_vs_actual $(DATA)/plan.tsv $(PLAN_STUDY_DATA)
	$< --plan $(DATA)/plan.tsv --datadir $(DATA) --out $@
