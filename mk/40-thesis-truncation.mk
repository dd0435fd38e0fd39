# Thesis truncation-error studies (issue 4): Figures 1.1-1.4, 4.1-4.7, Tables 4.1-4.3.
# Each table program writes one data file (all h readings and volume choices; key columns
# h_reading, volumes, level); the paper profile's cost of each pass is the plan's.  The rate tables
# compare one (h reading, volumes) slice at a time with the published rates: the slice is cut
# out with awk (header and comment lines kept) before rate_table reads it.
THESIS_TABLES := thesis_table4_1 thesis_table4_2 thesis_table4_3
THESIS_SLICES_4_1 := printed_voronoi printed_uniform
THESIS_SLICES_4_23 := printed_voronoi scaled_voronoi printed_uniform scaled_uniform
THESIS_RATES := $(foreach s,$(THESIS_SLICES_4_1),$(DATA)/thesis_table4_1_rates_$(s).tsv) \
                $(foreach t,4_2 4_3,$(foreach s,$(THESIS_SLICES_4_23),$(DATA)/thesis_table$(t)_rates_$(s).tsv))

DATAFILES += $(foreach t,$(THESIS_TABLES),$(DATA)/$(t).tsv) $(THESIS_RATES) \
             $(DATA)/thesis_fig_weights.tsv $(DATA)/thesis_fig1_1_particles.tsv \
             $(DATA)/thesis_fig4_1_particles.tsv $(DATA)/thesis_connectivity_particles.tsv
FIGFILES  += $(foreach f,fig1_1 fig1_2 fig1_3 fig1_4 fig4_1 fig4_2 fig4_3 fig4_4 fig4_5 fig4_6 fig4_7 speed_accuracy,$(FIGOUT)/thesis_$(f).svg)

# --- data ------------------------------------------------------------------------------
$(DATA)/thesis_table4_%.tsv: $(BUILD)/thesis_table4_%
	$(call store_recheck,$<,5$(,)6$(,)7)
	$< --profile $(PROFILE) --out $@
	@touch $@  # a fully cached rerun leaves the file as it was

$(DATA)/thesis_fig_weights.tsv: $(BUILD)/thesis_fig_weights
	$< --out $@
$(DATA)/thesis_fig1_1_particles.tsv: $(BUILD)/thesis_fig_distribution
	$< --dx 2^-3 --seed 1 --particles $@ --cells $(DATA)/thesis_fig1_2_cells.tsv
$(DATA)/thesis_fig4_1_particles.tsv: $(BUILD)/thesis_fig_distribution
	$< --dx 2^-5 --seed 1 --particles $@
$(DATA)/thesis_connectivity_particles.tsv: $(BUILD)/thesis_fig_connectivity
	$< --particles $@ --edges $(DATA)/thesis_connectivity_edges.tsv

# One rate table per (table, h reading, volumes): slice, then rate_table against the
# published long-format table (rates judged only at the document's levels).
thesis_key = $(if $(filter 4_3,$(1)),weight$(,)operator$(,)function,weight$(,)function)
, := ,
$(DATA)/thesis_table%_rates_printed_voronoi.tsv $(DATA)/thesis_table%_rates_scaled_voronoi.tsv \
$(DATA)/thesis_table%_rates_printed_uniform.tsv $(DATA)/thesis_table%_rates_scaled_uniform.tsv: \
    $(DATA)/thesis_table%.tsv $(BUILD)/rate_table tables/published/thesis_table%_long.tsv
	@for s in printed_voronoi scaled_voronoi printed_uniform scaled_uniform; do \
	  r=$${s%_*}; v=$${s#*_}; out=$(DATA)/thesis_table$*_rates_$$s.tsv; \
	  awk -F'\t' -v r=$$r -v v=$$v '/^#/ { print; next } !h++ { for (i=1;i<=NF;i++) c[$$i]=i; print; next } $$c["h_reading"]==r && $$c["volumes"]==v' $< > $$out.slice; \
	  if [ $$(grep -vc '^#' $$out.slice) -le 1 ]; then rm -f $$out.slice; continue; fi; \
	  $(BUILD)/rate_table --data $$out.slice --published tables/published/thesis_table$*_long.tsv \
	    --key $(call thesis_key,$*) --out $$out || exit 1; \
	  rm -f $$out.slice; \
	done

# --- figures ---------------------------------------------------------------------------
$(FIGOUT)/thesis_fig1_1.svg: figures/thesis_fig1_1.gp figures/style.gp $(DATA)/thesis_fig1_1_particles.tsv
$(FIGOUT)/thesis_fig1_2.svg: figures/thesis_fig1_2.gp figures/style.gp $(DATA)/thesis_fig1_1_particles.tsv
$(FIGOUT)/thesis_fig1_3.svg: figures/thesis_fig1_3.gp figures/thesis_connectivity.gp figures/style.gp $(DATA)/thesis_connectivity_particles.tsv
$(FIGOUT)/thesis_fig1_4.svg: figures/thesis_fig1_4.gp figures/thesis_connectivity.gp figures/style.gp $(DATA)/thesis_connectivity_particles.tsv
$(FIGOUT)/thesis_fig4_1.svg: figures/thesis_fig4_1.gp figures/style.gp $(DATA)/thesis_fig4_1_particles.tsv
$(FIGOUT)/thesis_fig4_2.svg: figures/thesis_fig4_2.gp figures/style.gp $(DATA)/thesis_fig_weights.tsv
$(FIGOUT)/thesis_fig4_4.svg: figures/thesis_fig4_4.gp figures/style.gp $(DATA)/thesis_fig_weights.tsv
$(FIGOUT)/thesis_fig4_3.svg: figures/thesis_fig4_3.gp figures/thesis_errors.gp figures/style.gp $(DATA)/thesis_table4_1.tsv tables/published/thesis_table4_1_long.tsv
$(FIGOUT)/thesis_fig4_5.svg: figures/thesis_fig4_5.gp figures/thesis_errors.gp figures/style.gp $(DATA)/thesis_table4_2.tsv tables/published/thesis_table4_2_long.tsv
$(FIGOUT)/thesis_fig4_6.svg: figures/thesis_fig4_6.gp figures/thesis_errors.gp figures/style.gp $(DATA)/thesis_table4_3.tsv tables/published/thesis_table4_3_long.tsv
$(FIGOUT)/thesis_fig4_7.svg: figures/thesis_fig4_7.gp figures/thesis_errors.gp figures/style.gp $(DATA)/thesis_table4_3.tsv tables/published/thesis_table4_3_long.tsv
$(FIGOUT)/thesis_speed_accuracy.svg: figures/thesis_speed_accuracy.gp figures/style.gp $(DATA)/thesis_table4_1.tsv $(DATA)/thesis_table4_2.tsv $(DATA)/thesis_table4_3.tsv
