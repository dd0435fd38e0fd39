# Thesis §4.2–4.3 (issue 5): the discrete Poisson and heat problems, Figures 4.8–4.11,
# Tables 4.4–4.7, each reproduced rate beside the published one (rate_table).
PDE_HEAT := 4_5 4_6 4_7
DATAFILES += $(DATA)/thesis_table4_4.tsv $(DATA)/thesis_table4_4_rates.tsv \
             $(foreach t,$(PDE_HEAT),$(DATA)/thesis_table$(t).tsv $(DATA)/thesis_table$(t)_rates.tsv) \
             $(foreach t,$(PDE_HEAT),$(DATA)/thesis_table$(t)_h15.tsv $(DATA)/thesis_table$(t)_h15_rates.tsv)
FIGFILES  += $(FIGOUT)/thesis_fig4_8.svg $(FIGOUT)/thesis_fig4_9.svg \
             $(FIGOUT)/thesis_fig4_10.svg $(FIGOUT)/thesis_fig4_11.svg \
             $(FIGOUT)/thesis_heat_readings.svg

$(DATA)/thesis_table4_4.tsv: $(BUILD)/thesis_table4_4
	$(call store_recheck,$<,5$(,)6)
	$< --profile $(PROFILE) --out $@
	@touch $@  # a fully cached rerun leaves the file as it was

$(DATA)/thesis_table4_4_rates.tsv: $(BUILD)/rate_table $(DATA)/thesis_table4_4.tsv tables/published/thesis_table4_4_long.tsv
	$< --data $(DATA)/thesis_table4_4.tsv --published tables/published/thesis_table4_4_long.tsv \
	  --key h_rule,weight --out $@

# One run of thesis_heat per table; it also writes the rows of the series that never
# blew up (…_finite.tsv), which is what rate_table reads.
$(DATA)/thesis_table%.tsv: $(BUILD)/thesis_heat
	$(call store_recheck,$< --table $(subst _,.,$*),5)
	$< --table $(subst _,.,$*) --profile $(PROFILE) --out $@ --rates-input $(DATA)/thesis_table$*_finite.tsv
	@touch $@ $(DATA)/thesis_table$*_finite.tsv

$(DATA)/thesis_table%_rates.tsv: $(BUILD)/rate_table $(DATA)/thesis_table%.tsv tables/published/thesis_table%_long.tsv
	$< --data $(DATA)/thesis_table$*_finite.tsv --published tables/published/thesis_table$*_long.tsv \
	  --key weight,theta --out $@

# The second reading of h, (2.6^4 2^-15 dx)^(1/4), as for the Poisson problem: separate
# data files (…_h15.tsv), rates against the same published values.  The shorter stem makes
# make prefer these rules over the generic ones above.
$(DATA)/thesis_table%_h15.tsv: $(BUILD)/thesis_heat
	$(call store_recheck,$< --table $(subst _,.,$*) --h-rule h15,5)
	$< --table $(subst _,.,$*) --h-rule h15 --profile $(PROFILE) --out $@ \
	  --rates-input $(DATA)/thesis_table$*_h15_finite.tsv
	@touch $@ $(DATA)/thesis_table$*_h15_finite.tsv

$(DATA)/thesis_table%_h15_rates.tsv: $(BUILD)/rate_table $(DATA)/thesis_table%_h15.tsv tables/published/thesis_table%_long.tsv
	$< --data $(DATA)/thesis_table$*_h15_finite.tsv --published tables/published/thesis_table$*_long.tsv \
	  --key weight,theta --out $@

$(FIGOUT)/thesis_fig4_8.svg: figures/thesis_fig4_8.gp figures/style.gp $(DATA)/thesis_table4_4.tsv tables/published/thesis_table4_4_long.tsv
$(FIGOUT)/thesis_fig4_9.svg: figures/thesis_fig4_9.gp figures/thesis_heat.gp figures/style.gp $(DATA)/thesis_table4_5.tsv tables/published/thesis_table4_5_long.tsv
$(FIGOUT)/thesis_fig4_10.svg: figures/thesis_fig4_10.gp figures/thesis_heat.gp figures/style.gp $(DATA)/thesis_table4_6.tsv tables/published/thesis_table4_6_long.tsv
$(FIGOUT)/thesis_fig4_11.svg: figures/thesis_fig4_11.gp figures/thesis_heat.gp figures/style.gp $(DATA)/thesis_table4_7.tsv tables/published/thesis_table4_7_long.tsv
$(FIGOUT)/thesis_heat_readings.svg: figures/thesis_heat_readings.gp figures/style.gp \
    $(foreach t,$(PDE_HEAT),$(DATA)/thesis_table$(t).tsv $(DATA)/thesis_table$(t)_h15.tsv)
