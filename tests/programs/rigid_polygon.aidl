// Issue 14: a Polygon written as literal coordinates and then placed by relations keeps its
// shape (it moves; no vertex is dragged).
units mm

solid house {
    solid walls {
        box = Rectangle(center=(0, 0), width=40, height=30)
    }
    solid roof {
        outline = Polygon([(0, 0), (50, 0), (25, 20)])
    }
    solid chimney {
        stack = Polygon([(0, 0), (6, 0), (6, 12), (0, 12)])
    }
    Above(roof, walls)
    AlignCenterX(roof, walls)
    RightOf(chimney, walls, gap=-12)
    AlignTop(chimney, roof)
}
