# Thesis truncation-error studies (issue 4): Figures 1.1-1.4, 4.1-4.7, Tables 4.1-4.3.
# Each table program writes one data file (all h readings and volume choices; key columns
# h_reading, volumes, level); its rule, the rate tables (one per h reading and volumes,
# rate_table --where) and the figures of its errors (4.3, 4.5-4.7) are the registry's
# (build/studies.mk, group truncation).
DATAFILES += $(DATA)/thesis_fig_weights.tsv $(DATA)/thesis_fig1_1_particles.tsv \
             $(DATA)/thesis_fig4_1_particles.tsv $(DATA)/thesis_connectivity_particles.tsv
FIGFILES  += $(foreach f,fig1_1 fig1_2 fig1_3 fig1_4 fig4_1 fig4_2 fig4_4 speed_accuracy,$(FIGOUT)/thesis_$(f).svg)

# --- data ---------------------------------------------------------------------------------
$(DATA)/thesis_fig_weights.tsv: $(BUILD)/thesis_fig_weights
	$< --out $@
$(DATA)/thesis_fig1_1_particles.tsv: $(BUILD)/thesis_fig_distribution
	$< --dx 2^-3 --seed 1 --particles $@ --cells $(DATA)/thesis_fig1_2_cells.tsv
$(DATA)/thesis_fig4_1_particles.tsv: $(BUILD)/thesis_fig_distribution
	$< --dx 2^-5 --seed 1 --particles $@
$(DATA)/thesis_connectivity_particles.tsv: $(BUILD)/thesis_fig_connectivity
	$< --particles $@ --edges $(DATA)/thesis_connectivity_edges.tsv

# --- figures ---------------------------------------------------------------------------
$(FIGOUT)/thesis_fig1_1.svg: figures/thesis_fig1_1.gp figures/style.gp $(DATA)/thesis_fig1_1_particles.tsv
$(FIGOUT)/thesis_fig1_2.svg: figures/thesis_fig1_2.gp figures/style.gp $(DATA)/thesis_fig1_1_particles.tsv
$(FIGOUT)/thesis_fig1_3.svg: figures/thesis_fig1_3.gp figures/thesis_connectivity.gp figures/style.gp $(DATA)/thesis_connectivity_particles.tsv
$(FIGOUT)/thesis_fig1_4.svg: figures/thesis_fig1_4.gp figures/thesis_connectivity.gp figures/style.gp $(DATA)/thesis_connectivity_particles.tsv
$(FIGOUT)/thesis_fig4_1.svg: figures/thesis_fig4_1.gp figures/style.gp $(DATA)/thesis_fig4_1_particles.tsv
$(FIGOUT)/thesis_fig4_2.svg: figures/thesis_fig4_2.gp figures/style.gp $(DATA)/thesis_fig_weights.tsv
$(FIGOUT)/thesis_fig4_4.svg: figures/thesis_fig4_4.gp figures/style.gp $(DATA)/thesis_fig_weights.tsv
$(FIGOUT)/thesis_speed_accuracy.svg: figures/thesis_speed_accuracy.gp figures/style.gp $(foreach f,$(STUDY_FILES_truncation),$(DATA)/$(f).tsv)
