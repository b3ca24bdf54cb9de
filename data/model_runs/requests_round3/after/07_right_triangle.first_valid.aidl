# A right-triangle plate with legs of 95.149 mm and 15.482 mm, 3.175 mm thick.
thickness 3.175 mm

solid plate {
    tri = Polygon([(0, 0), (95.149, 0), (0, 15.482)])
}
