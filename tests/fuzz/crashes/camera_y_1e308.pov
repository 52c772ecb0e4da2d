#declare Mirage_Preset = "paper";
camera { location <0, 1e308, 0> look_at <0, 1e308, 1> }
