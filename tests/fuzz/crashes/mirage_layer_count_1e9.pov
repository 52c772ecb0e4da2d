#declare Mirage_Preset = "paper";
#declare Mirage_Layers = "uniform";
#declare Mirage_Layer_Count = 1e9;
