#declare Mirage_Profile = "superior";
#declare Mirage_Eta0 = 1.1;
#declare Mirage_Eta1 = 0.4584;
#declare Mirage_Alpha = 1000;
camera { location <0, 10, 0> look_at <0, 9, 100> }
