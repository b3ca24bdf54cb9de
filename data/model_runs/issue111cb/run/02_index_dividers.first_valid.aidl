# Request (office): a set of 5 alphabet dividers for my A4 filing box, 3 mm frosted acrylic.
# - Each divider is 310 x 220 mm with an index tab 56 mm wide standing 15 mm above its top
#   edge. The tabs step across the divider, one position per divider, 60 mm apart, the first
#   5 mm in from the left edge, so all five read at once when stacked.
# - On each tab its range engraved filled in bold, at most 46 mm wide, 8 mm high:
#   "A - E", "F - J", "K - O", "P - T", "U - Z".
# - All outside corners rounded r3 (nothing to snag the papers), also where the tab meets
#   the top edge.
# - Cut as 5 separate parts; shown standing in the box 20 mm apart.

thickness 3 mm

labels = ["A - E", "F - J", "K - O", "P - T", "U - Z"]
n = len(labels)

def divider(k=0, label="A - E") -> solid {
    body = Rectangle(center=(0, 0), width=310, height=220)
    # the tab: its bottom overlaps the body by 1 mm so the two merge into one outline
    tab = Rectangle(center=(-155 + 5 + 28 + 60 * k, 110 + 7.5 - 0.5), width=56, height=16)
    drawing name {
        word = Text(label, position=(-155 + 5 + 28 + 60 * k, 117.5), size=8, valign="middle",
                    font="sans:Bold", fill=true, max_width=46)
    }
    Fillet(3)
}

assembly dividers {
    for k in range(n) {
        d = divider(k=k, label=labels[k])
    }
    for k in range(1, n) {
        RightOf(d[k], d[k - 1], gap=5)
        AlignBottom(d[k], d[k - 1])
    }
    for k in range(n) {
        Place(d[k], position=(0, 20 * k, 110), rotation=(90 deg, 0, 0))
    }

    assert len(d) == 5
    assert d[0].body.width == 310 mm and d[0].body.height == 220 mm
    assert d[0].tab.width == 56 mm
    assert d[0].tab.bb.top - d[0].body.bb.top == 15 mm, "tab stands 15 mm above the top"
    assert d[0].tab.bb.left - d[0].body.bb.left == 5 mm, "first tab 5 mm in from the left"
    assert (d[4].tab.bb.left - d[4].body.bb.left) - (d[0].tab.bb.left - d[0].body.bb.left) == 4 * 60 mm
    assert d[4].tab.bb.right <= d[4].body.bb.right, "the last tab stays on the divider"
    assert d[2].name.word.bb.width <= 46 mm
}
