#declare Mirage_Preset = "paper";
#declare Mirage_Tolerance = 1e-300;
camera { location <0, 1.5, 0> look_at <0, 1.5, 1> }
