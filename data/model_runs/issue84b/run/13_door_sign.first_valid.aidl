# Door sign: a 180 x 60 mm plate with 8 mm corner radii, hung by two 4 mm holes
# 10 mm from the top edge and 20 mm from the sides; "PRIVATE" engraved 18 mm high
# in the middle and "please knock" 7 mm high under it; an engraved line border
# 4 mm inside the edge.

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=180, height=60, corner_radius=8)
    hole hang {
        a = Circle(center=(-90 + 20, 30 - 10), diameter=4)
        b = Circle(center=(90 - 20, 30 - 10), diameter=4)
    }
    drawing text {
        title = Text("PRIVATE", (0, 2), size=18, valign="middle")
        sub = Text("please knock", (0, -18), size=7, valign="middle")
        border = RoundedRectangle(center=(0, 0), width=172, height=52, corner_radius=4)
    }
}
