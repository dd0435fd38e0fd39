# The front page's scoreboard: status counts over the rate tables of the reproductions
# (the thesis tables in the setting the thesis prints: printed h, Voronoi volumes).
SCORE_TABLES := $(DATA)/imoto_table1.tsv \
  $(foreach t,4_1 4_2 4_3,$(DATA)/thesis_table$(t)_rates_printed_voronoi.tsv) \
  $(foreach t,4_4 4_5 4_6 4_7,$(DATA)/thesis_table$(t)_rates.tsv)
DATAFILES += $(DATA)/scoreboard.tsv

$(DATA)/scoreboard.tsv: $(BUILD)/scoreboard $(SCORE_TABLES)
	$< --profile $(PROFILE) --tables $(subst $(eval) ,$(,),$(strip $(SCORE_TABLES))) --out $@
