# Koba & Sato (issue 6): Corollary 7.1 checked exactly against the printed values;
# Theorems 1.3-1.6 evaluated on jittered-grid Voronoi cells; Figures 1-2.
KS_SIDE := $(DATA)/koba_sato_bounds_summary.tsv $(DATA)/koba_sato_bounds_constants.tsv \
           $(DATA)/koba_sato_bounds_hypotheses.tsv $(DATA)/koba_sato_fig_particles.tsv \
           $(DATA)/koba_sato_fig_cells.tsv $(DATA)/koba_sato_fig_circles.tsv
DATAFILES += $(DATA)/koba_sato_cor71.tsv $(DATA)/koba_sato_bounds.tsv $(KS_SIDE)
FIGFILES  += $(FIGOUT)/koba_sato_fig1.svg $(FIGOUT)/koba_sato_fig2.svg \
             $(FIGOUT)/koba_sato_bounds.svg

$(DATA)/koba_sato_cor71.tsv: $(BUILD)/koba_sato_cor71 tables/published/koba_sato_cor71.tsv
	$< --profile $(PROFILE) --out $@ --published tables/published/koba_sato_cor71.tsv

# One run writes the cases, and beside them the summary, constants, hypotheses and the
# Figure 1-2 data (the cases file is written last, so it is the newest).
$(DATA)/koba_sato_bounds.tsv: $(BUILD)/koba_sato_bounds
	$< --profile $(PROFILE) --out $@
	@touch $(KS_SIDE)  # side outputs no older than the cases file: no spurious remakes
$(KS_SIDE): $(DATA)/koba_sato_bounds.tsv ;

$(FIGOUT)/koba_sato_fig1.svg: figures/koba_sato_fig1.gp figures/style.gp $(DATA)/koba_sato_fig_particles.tsv $(DATA)/koba_sato_fig_circles.tsv
$(FIGOUT)/koba_sato_fig2.svg: figures/koba_sato_fig2.gp figures/style.gp $(DATA)/koba_sato_fig_cells.tsv $(DATA)/koba_sato_fig_particles.tsv $(DATA)/koba_sato_fig_circles.tsv
$(FIGOUT)/koba_sato_bounds.svg: figures/koba_sato_bounds.gp figures/style.gp $(DATA)/koba_sato_bounds.tsv
