# imoto-generalized-particle-method (issue 3): Figures 1-5, Table 1, regularity indicators.
# Figure 5's data (imoto_fig5_table1: all nine weights, m = 1, 3, 5, one fused pass per
# (level, m), cached per unit) with the (Pi3) printed-constant check beside it, and Table 1's
# rates (judged at the document's levels 2^-11/2^-12 from the store: gpm store-rates): their
# rules are the registry's (build/studies.mk).
DATAFILES += $(DATA)/imoto_regularity_cover.tsv $(DATA)/imoto_figs_particles.tsv
FIGFILES  += $(FIGOUT)/imoto_fig4.svg $(FIGOUT)/imoto_fig2.svg $(FIGOUT)/imoto_fig3.svg \
             $(FIGOUT)/imoto_covering.svg

# Covering radius over levels and seeds, the counter-example, and d_N by the LP.
$(DATA)/imoto_regularity_cover.tsv: $(BUILD)/imoto_regularity
	$< --profile $(PROFILE) --out $@ --out-example $(DATA)/imoto_regularity_example.tsv \
	  --out-deviation $(DATA)/imoto_regularity_deviation.tsv

# Figures 1-4 as data (particles, Voronoi edges, Figure 3's two distributions and discs).
$(DATA)/imoto_figs_particles.tsv: $(BUILD)/imoto_figs1_4
	$< --prefix $(DATA)/imoto_figs

$(FIGOUT)/imoto_fig4.svg: figures/imoto_fig4.gp figures/style.gp $(DATA)/imoto_figs_particles.tsv
$(FIGOUT)/imoto_fig2.svg: figures/imoto_fig2.gp figures/style.gp $(DATA)/imoto_figs_particles.tsv
$(FIGOUT)/imoto_fig3.svg: figures/imoto_fig3.gp figures/style.gp $(DATA)/imoto_figs_particles.tsv
$(FIGOUT)/imoto_covering.svg: figures/imoto_covering.gp figures/style.gp $(DATA)/imoto_regularity_cover.tsv
