#declare Mirage_Preset = "paper";
camera { location <0, 1.5, 1e999> }
