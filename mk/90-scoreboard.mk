# The front page's scoreboard: status counts over the rate tables of the reproductions
# (the thesis tables in the setting the thesis prints: printed h, Voronoi volumes).
SCORE_TABLES := $(foreach r,$(STUDY_SCORED_RATES),$(DATA)/$(r).tsv)
DATAFILES += $(DATA)/scoreboard.tsv

$(DATA)/scoreboard.tsv: $(BUILD)/scoreboard $(SCORE_TABLES)
	$< --profile $(PROFILE) --tables $(subst $(eval) ,$(,),$(strip $(SCORE_TABLES))) --out $@
