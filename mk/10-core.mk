# The core's own checks (foundation issue): weight properties and errata, Voronoi cells.
# core_voronoi's data rule is the registry's (build/studies.mk).
DATAFILES += $(DATA)/core_weights.tsv $(DATA)/core_operator_errata.tsv
FIGFILES  += $(FIGOUT)/core_covering_radius.svg

$(DATA)/core_weights.tsv: $(BUILD)/core_weights
	$< --profile $(PROFILE) --out $@ --errata $(DATA)/core_weights_errata.tsv

$(DATA)/core_operator_errata.tsv: $(BUILD)/core_operator_errata
	$< --profile $(PROFILE) --out $@

$(FIGOUT)/core_covering_radius.svg: figures/core_covering_radius.gp figures/style.gp $(DATA)/core_voronoi.tsv
