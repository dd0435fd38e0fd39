# The software environment of the run (compiler, libraries, CPU), read from the machine.
DATAFILES += $(DATA)/environment.tsv
$(DATA)/environment.tsv: tables/environment.sh $(BUILD)/gpm
	@mkdir -p $(DATA)
	bash $< $(BUILD) $@
