#!/usr/bin/env bash
# model_cases.sh CASES MODEL.xml...: writes to CASES the library's elements of
# the models, as the cases entry_host evaluates (entry_host.c reads them). Per model: its
# units (Param_Unit, as c_gtunts reports them), its Reference_Strings, then one
# line per element that names libusrsub.so:
#   coupler NDISP NPAR PAR...         Constraint_Coupler: COUSUB, COUXX, COUXX2
#   gfosub ENTRY NPAR PAR...          Force_Vector_TwoBody/OneBody (ForceAndTorque)
#   fiesub ENTRY NPAR PAR...          Force_Field
#   yfosub NSTATE NPAR PAR...         Force_StateEqn: YFOSUB and its partials
# ENTRY is usrsub_fnc_name, or the element's default. Attributes are read
# from the models' own layout (attribute="value", any line breaks).
set -euo pipefail
cases=$1
shift
for model in "$@"; do
  tr '\n\r\t' '   ' <"$model" | awk -v model="$(basename "$model")" '
    function attr(s, name,    m) { # value of name="..." in s, or ""
      if (match(s, "[ \t]" name "=\"[^\"]*\"") == 0) return ""
      m = substr(s, RSTART + 1, RLENGTH - 1)
      sub(/^[^"]*"/, "", m); sub(/"$/, "", m)
      return m
    }
    function size(table, name, quantity) {
      name = toupper(name); gsub(/_/, "", name)
      if (!(name in table)) { print "model_cases: " model ": unknown " quantity " unit " name > "/dev/stderr"; failed = 1; exit 1 }
      return table[name]
    }
    function user_list(s,    n, k, p, v, out) { # "NPAR PAR..." from USER(...)
      sub(/^[ ]*USER[ ]*\(/, "", s); sub(/\)[ ]*$/, "", s)
      n = split(s, p, /[ ,]+/); out = ""; v = 0
      for (k = 1; k <= n; ++k) if (p[k] != "") { out = out " " p[k]; ++v }
      return v out
    }
    BEGIN {
      RS = "<"
      length_si["MILLIMETER"] = 1e-3; length_si["MM"] = 1e-3; length_si["CENTIMETER"] = 1e-2
      length_si["CM"] = 1e-2; length_si["METER"] = 1; length_si["M"] = 1
      force_si["NEWTON"] = 1; force_si["N"] = 1; force_si["KILONEWTON"] = 1e3; force_si["KNEWTON"] = 1e3
      mass_si["KILOGRAM"] = 1; mass_si["KG"] = 1; mass_si["GRAM"] = 1e-3
      mass_si["MEGAGRAM"] = 1e3; mass_si["TONNE"] = 1e3
      time_si["SECOND"] = 1; time_si["SEC"] = 1; time_si["MILLISECOND"] = 1e-3
      print "model " model
    }
    {
      tag = $1; sub(/\/?>.*$/, "", tag)
      if (tag == "Param_Unit")
        printf "units 1 %.17g %.17g %.17g %.17g\n", size(time_si, attr($0, "time_unit"), "time"),
               size(length_si, attr($0, "length_unit"), "length"),
               size(force_si, attr($0, "force_unit"), "force"), size(mass_si, attr($0, "mass_unit"), "mass")
      else if (tag == "Reference_String")
        print "string " attr($0, "id") " " attr($0, "string")
      if (attr($0, "usrsub_param_string") == "" || attr($0, "usrsub_dll_name") !~ /usrsub/) next
      user = user_list(attr($0, "usrsub_param_string")); entry = attr($0, "usrsub_fnc_name")
      if (tag == "Constraint_Coupler")
        print "coupler " (attr($0, "joint3_id") != "" ? 3 : 2) " " user
      else if (tag == "Force_Vector_TwoBody" || tag == "Force_Vector_OneBody")
        print "gfosub " (entry != "" ? entry : "GFOSUB") " " user
      else if (tag == "Force_Field")
        print "fiesub " (entry != "" ? entry : "FIESUB") " " user
      else if (tag == "Force_StateEqn")
        print "yfosub " attr($0, "num_state") " " user
    }'
done >"$cases.tmp"
mv "$cases.tmp" "$cases"
