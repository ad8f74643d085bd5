# class: format_walk
# expect: contained
# attack: the template is spelled with chr() codes, %-formatting and str.join, then walks print's globals to sys.modules['os'].environ
codes = [123, 48, 46, 95, 95, 103, 108, 111, 98, 97, 108, 115, 95, 95]
head = "".join(map(chr, codes))  # "{0.__globals__"
template = "%s[sys].modules[os].environ[%s]}" % (head, "ROBOSCRIPT_TEST_SECRET")
try:
    print(template.format(print))
except Exception as exc:
    print("refused:", str(exc)[:80])
wide = "%s[sys].orig_argv}" % head
try:
    print(wide.format(print))
except Exception as exc:
    print("refused:", str(exc)[:80])
bbox = get_3d_bbox("bowl")
print("bowl box", bbox)
