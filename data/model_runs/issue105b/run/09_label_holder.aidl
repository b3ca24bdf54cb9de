# Drawer label holder, two layers of 2 mm acrylic screwed to the drawer front.
# Both layers are 80 x 40 mm with 3 mm rounded corners and two 3.2 mm screw holes
# 4.5 mm in from the left and right ends, centered vertically.
# Front layer: a 54 x 24 mm window (2 mm corner radius), centered.
# Back (spacer) layer: a 62 mm wide channel, open at the top edge, 34 mm deep
# from the top edge: the slot into which a 60 x 30 mm paper label slides.
# The two layers lie side by side on the sheet, 5 mm apart.

units mm
thickness 2 mm

def layer_outline() -> solid {
    body = RoundedRectangle(center=(0, 0), width=80, height=40, corner_radius=3)
    hole screw {
        c = Circle(center=(-35.5, 0), diameter=3.2)
    }
    At(screw.c.center, body.left.midpoint, dx=4.5)
    axis = Line(body.top.midpoint, body.bottom.midpoint, construction=true)
    screw2 = Mirrored(screw, about=axis)
}

assembly holder {
    front = layer_outline()
    hole window {
        w = RoundedRectangle(center=(0, 0), width=54, height=24, corner_radius=2)
    }
    CutInto(window, front)
    CenterInside(window, front.body)

    spacer = layer_outline()
    hole channel {
        c = Rectangle(center=(90, 5), width=62, height=36)
    }
    CutInto(channel, spacer)
    AlignCenterX(channel, spacer.body)
    # 34 mm deep below the top edge (36 tall: runs 2 mm out past it)
    channel.c.bb.bottom == spacer.body.bb.top - 34

    RightOf(spacer, front, gap=5)
    AlignCenterY(spacer, front)
}
