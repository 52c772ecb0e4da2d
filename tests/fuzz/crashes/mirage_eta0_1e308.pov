#declare Mirage_Profile = "inferior";
#declare Mirage_Eta0 = 1e308;
#declare Mirage_Eta1 = 0.1;
#declare Mirage_Alpha = 1;
camera { location <0, 1.5, 0> look_at <0, 1.5, 1> }
