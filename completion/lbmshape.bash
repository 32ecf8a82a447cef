# Bash completion for lbmshape (zsh: autoload bashcompinit && bashcompinit,
# then source this file). The commands and options are read from
# `lbmshape --help` and `lbmshape COMMAND --help` when completing, so they
# are always the installed binary's own; after an option that lists its
# values (--color {none,curvature}, --align, --sdf, --extract) those values
# complete, after --device the devices `lbmshape info` lists and
# `reference`; files complete everywhere else.
_lbmshape()
{
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]}
  local binary=${COMP_WORDS[0]} command="" word skip=""
  local main
  main=$("$binary" --help 2>/dev/null)
  # The command is the first word that is neither an option nor the value
  # of one (--device 0 denoise ...): options with a value show a type in
  # the help (--device TEXT, --sdf ENUM:...).
  local valued
  valued=" $(grep -o -- '--[a-z][a-z-]* [A-Z]' <<<"$main" | cut -d' ' -f1 | tr '\n' ' ') "
  for word in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do
    if [[ -n $skip ]]; then skip=""; continue; fi
    if [[ $word == -* ]]; then
      [[ $valued == *" $word "* ]] && skip=1
      continue
    fi
    command=$word
    break
  done
  local help=$main
  [[ -n $command ]] && help=$("$binary" "$command" --help 2>/dev/null)
  # An option's listed values, as the help prints them: --color TEXT:{none,curvature},
  # --align ENUM:{none,center,fit}.
  local values
  values=$(grep -oh -- "$prev [A-Z]*:{[^}]*}" <<<"$help"$'\n'"$main" | sed 's/.*{\(.*\)}/\1/; s/,/ /g')
  if [[ $prev == --device ]]; then
    values="reference $("$binary" info 2>/dev/null | sed -n 's/^[* ] \([0-9]\+\): .*/\1/p' | tr '\n' ' ')"
  fi
  if [[ -n $values ]]; then
    values=$(tr ' ' '\n' <<<"$values" | sort -u)
    mapfile -t COMPREPLY < <(compgen -W "$values" -- "$cur")
    return
  fi
  if [[ $cur == -* ]]; then
    local options
    options=$(grep -o -- '--[a-z][a-z-]*' <<<"$help" | sort -u)
    mapfile -t COMPREPLY < <(compgen -W "$options" -- "$cur")
    return
  fi
  if [[ -z $command && $valued != *" $prev "* ]]; then
    # The commands: the words under "Subcommands:".
    local commands
    commands=$(sed -n '/^Subcommands:/,$s/^  \([a-z]\+\) .*/\1/p' <<<"$main")
    mapfile -t COMPREPLY < <(compgen -W "$commands" -- "$cur")
    return
  fi
  mapfile -t COMPREPLY < <(compgen -f -- "$cur")
}
complete -o filenames -F _lbmshape lbmshape
