# Bash completion for lbmshape (zsh: autoload bashcompinit && bashcompinit,
# then source this file). The commands and options are read from
# `lbmshape --help` and `lbmshape COMMAND --help` when completing, so they
# are always the installed binary's own; files complete everywhere else, and
# the values an option lists ({none,curvature}) complete after it.
_lbmshape()
{
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]}
  local binary=${COMP_WORDS[0]} command="" word
  for word in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do
    [[ $word != -* ]] && { command=$word; break; }
  done
  local help
  if [[ -z $command ]]; then
    help=$("$binary" --help 2>/dev/null)
    if [[ $cur != -* ]]; then
      # The commands: the words under "Subcommands:".
      local commands
      commands=$(sed -n '/^Subcommands:/,$s/^  \([a-z]\+\) .*/\1/p' <<<"$help")
      mapfile -t COMPREPLY < <(compgen -W "$commands" -- "$cur")
      return
    fi
  else
    help=$("$binary" "$command" --help 2>/dev/null)
  fi
  # An option's listed values, as CLI11 prints them: --color TEXT:{none,curvature}
  local values
  values=$(grep -o -- "$prev [A-Z]*:{[^}]*}" <<<"$help" | sed 's/.*{\(.*\)}/\1/; s/,/ /g')
  if [[ -n $values ]]; then
    mapfile -t COMPREPLY < <(compgen -W "$values" -- "$cur")
    return
  fi
  if [[ $cur == -* ]]; then
    local options
    options=$(grep -o -- '--[a-z][a-z-]*' <<<"$help" | sort -u)
    mapfile -t COMPREPLY < <(compgen -W "$options" -- "$cur")
    return
  fi
  mapfile -t COMPREPLY < <(compgen -f -- "$cur")
}
complete -o filenames -F _lbmshape lbmshape
